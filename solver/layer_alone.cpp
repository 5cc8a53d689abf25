// Nothing: a layer of the solver linked on its own (CMakeLists.txt) needs a source of its own.

# The Debian package (CPack, DEB generator): `cmake --build build --target package` makes
# linkage_<version>_amd64.deb in the build directory, installing to /usr what `cmake --install`
# installs. Its dependencies are the shared libraries the programs load, found by dpkg-shlibdeps
# (package dpkg-dev, with file): Qt 6 Core, Gui (with its platform plugins), Widgets and Svg,
# QCustomPlot's Qt 6 build (which brings PrintSupport), giflib, the C++ runtime. Fonts come with
# them (libqt6gui6 needs fontconfig, whose configuration needs a font package, fonts-dejavu-core
# first). README.md, "Debian package", says why each one is there.
set(LINKAGE_PACKAGE_MAINTAINER
    "Seed 8f76a2ca maintainers <maintainers@users.noreply.h-seed-8f76a2ca.example>"
    CACHE STRING "The Debian package's Maintainer field")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME linkage)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "The linkage developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "planar linkage editor with an exact kinematic core")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER ${LINKAGE_PACKAGE_MAINTAINER})
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Debian's extended description: CPack puts the summary above it as the synopsis line and keeps
# these lines as they are (lintian: under 80 characters with the leading space).
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "Draw links, pins and slots; a constraint solver moves the mechanism, and the
position, velocity and acceleration of any point come out exact, from linear
solves with the constraint Jacobian. The editor (linkage) draws and edits
mechanisms live, animates them, shows every instant centre with its Kennedy
lines, plots motion curves and checks designs (transmission angles, limit
positions, Grashof, parameter studies); linkage-cli writes motion tables,
instant centres, design checks and figures for scripts, and the Python module
linkage gives the same answers as numpy arrays. Example mechanisms
include the Wanzer needle bar, slider-cranks, four-bars and a lockstitch arm
shaft.")
# The Python module (app/python, when built) is for the Python it was built with, whose minor
# version fixes its ABI, and makes numpy arrays: the interpreter and numpy, not shared libraries
# the module links, so dpkg-shlibdeps cannot name them.
if(TARGET linkage_python)
  string(REPLACE "." ";" v "${LINKAGE_PYTHON_VERSION}")
  list(GET v 0 major)
  list(GET v 1 minor)
  math(EXPR next "${minor} + 1")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
      "python3 (>= ${major}.${minor}), python3 (<< ${major}.${next}), python3-numpy")
endif()
# Debian policy: every package has /usr/share/doc/<package>/copyright, and a native package (no
# Debian revision) its changelog.gz, compressed with gzip -9n (no name, no time: reproducible).
install(FILES ${PROJECT_SOURCE_DIR}/cmake/copyright DESTINATION share/doc/linkage)
# Made when configuring, so that `cmake --install` needs no build target for it.
set_property(DIRECTORY APPEND
             PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/cmake/changelog)
execute_process(COMMAND gzip -9n -c ${PROJECT_SOURCE_DIR}/cmake/changelog
                OUTPUT_FILE ${PROJECT_BINARY_DIR}/changelog.gz COMMAND_ERROR_IS_FATAL ANY)
install(FILES ${PROJECT_BINARY_DIR}/changelog.gz DESTINATION share/doc/linkage)
include(CPack)

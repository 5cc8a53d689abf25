#include "cli_common.h"

#include <cstdio>
#include <iostream>

#include "linkage/io/atomic_file.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"

namespace linkage::cli {

std::string executablePath;

int exitFor(const Status& s) {
  switch (s.code) {
    case StatusCode::Ok:
      return kOk;
    case StatusCode::Unreachable:
    case StatusCode::Singular:
    case StatusCode::NotConverged:
      return kUnreachable;
    default:
      return kBadInput;
  }
}

void error(const std::string& message) {
  std::cerr << "linkage-cli: " << message << "\n";
}
void note(const std::string& message) {
  std::cerr << "linkage-cli: note: " << message << "\n";
}

std::optional<Mechanism> openModel(const std::string& nameOrPath) {
  std::optional<std::string> path = resolveModel(nameOrPath, executablePath);
  if (!path) {
    std::string msg = nameOrPath + ": no such file, and no example of that name";
    const std::vector<std::string> names = listExamples(executablePath);
    if (!names.empty()) {
      msg += " (examples:";
      for (const std::string& n : names) msg += " " + n;
      msg += ")";
    }
    error(msg);
    return std::nullopt;
  }
  LoadResult r = loadMechanismFile(*path);
  if (!r.mechanism) {
    error(r.error);
    return std::nullopt;
  }
  return std::move(*r.mechanism);
}

std::optional<Mechanism> openDrivenModel(const std::string& nameOrPath) {
  std::optional<Mechanism> m = openModel(nameOrPath);
  if (m && !m->driver) {
    error(nameOrPath +
          ": the mechanism has no driver: add \"driver\": {\"joint\": <pin index>, ...}");
    return std::nullopt;
  }
  return m;
}

int writeOutput(const std::string& path, const std::string& text) {
  if (path.empty()) {
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fflush(stdout);
    return kOk;
  }
  const WriteResult w = writeFileAtomically(path, text);
  if (!w.ok) error(w.error);
  return w.ok ? kOk : kFailure;
}

int prepare(Kinematics& k, const Mechanism& m) {
  const Status s = k.load(m);
  for (const Note& n : k.notes()) note(n.text);
  if (!s.ok()) {
    error(s.message);
    return exitFor(s);
  }
  return kOk;
}

std::optional<std::vector<PointId>> outputPoints(const Mechanism& m,
                                                 const std::vector<std::string>& asked) {
  if (asked.empty()) {
    if (m.outputs.empty()) {
      error("the model names no output points: give one or more --point body.point");
      return std::nullopt;
    }
    return m.outputs;
  }
  std::vector<PointId> ids;
  for (const std::string& a : asked) {
    std::optional<PointId> id = m.findPoint(a);
    if (!id) {
      const size_t dot = a.rfind('.');
      if (dot == std::string::npos)
        error("--point " + a + ": expected body.point");
      else if (!m.bodyNamed(a.substr(0, dot)))
        error("--point " + a + ": no body \"" + a.substr(0, dot) + "\"");
      else
        error("--point " + a + ": no point \"" + a.substr(dot + 1) + "\" on body \"" +
              a.substr(0, dot) + "\"");
      return std::nullopt;
    }
    ids.push_back(*id);
  }
  return ids;
}

}  // namespace linkage::cli

#include "cli_common.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "linkage/io/atomic_file.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "linkage/io/numbers.h"

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

std::optional<double> number(const std::string& option, const std::string& text) {
  std::optional<double> v = parseNumber(text);
  if (!v) error(option + ": \"" + text + "\" is not a number");
  return v;
}

std::optional<double> positiveNumber(const std::string& option, const std::string& text) {
  std::optional<double> v = number(option, text);
  if (v && !(*v > 0)) {
    error(option + ": must be positive, got " + text);
    return std::nullopt;
  }
  return v;
}

std::optional<long long> wholeNumber(const std::string& option, const std::string& text) {
  long long v = 0;
  const char* end = text.data() + text.size();
  auto [p, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || p != end) {
    error(option + ": \"" + text + "\" is not a whole number");
    return std::nullopt;
  }
  return v;
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

bool isHelp(const std::string& arg) {
  return arg == "--help" || arg == "-h";
}

Arguments& Arguments::value(std::string option, Reader read) {
  values_.emplace_back(std::move(option), std::move(read));
  return *this;
}

Arguments& Arguments::flag(std::string option, bool& on) {
  flags_.emplace_back(std::move(option), &on);
  return *this;
}

std::optional<int> Arguments::read(int argc, char** argv, std::string& model) const {
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (isHelp(a)) {
      std::cout << help_;
      return kOk;
    }
    auto value =
        std::find_if(values_.begin(), values_.end(), [&](auto& v) { return v.first == a; });
    auto flag = std::find_if(flags_.begin(), flags_.end(), [&](auto& f) { return f.first == a; });
    if (value != values_.end()) {
      if (i + 1 >= argc) {
        error(a + ": needs a value");
        return kBadInput;
      }
      if (!value->second(a, argv[++i])) return kBadInput;
    } else if (flag != flags_.end()) {
      *flag->second = true;
    } else if (!a.empty() && a[0] == '-' && a != "-") {
      error(command_ + ": unknown option " + a + " (see linkage-cli " + command_ + " --help)");
      return kBadInput;
    } else if (model.empty()) {
      model = a;
    } else {
      error(command_ + ": more than one MODEL given: " + model + ", " + a);
      return kBadInput;
    }
  }
  if (model.empty()) {
    error(command_ + ": no MODEL given (see linkage-cli " + command_ + " --help)");
    return kBadInput;
  }
  return std::nullopt;
}

}  // namespace linkage::cli

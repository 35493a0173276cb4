// check_layers: fails, naming file:line, when a file includes a header of a higher layer.
//
//   check_layers <source root>
//
// Reads every #include "..." of include/, src/ and apps/ under <source root> (the
// `#include "slideline/<layer>/..."` form and includes relative to the including file) and checks
// each against the layer table below (docs/architecture.md, "Layers"). Exit 0 when every include
// points down or sideways within its own layer; 1 with one line per violation; 2 on a usage error.
// A directory missing from the table, or a quoted include that resolves to no file, is a violation
// too: a new module must be given a layer.
#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <regex>
#include <string>
#include <string_view>
#include <vector>

namespace fs = std::filesystem;

namespace {

/// The layer table: each layer and the layers its files may include (besides its own). Kernels
/// (core, material, mesh, element) know nothing of decks; `model`, the plain description of a
/// deck, includes only core and is read from contact up (the contact factories turn a card into
/// an interface); `scenarios` (the two-block problems, which write and read histories) sits
/// between io and the apps.
struct Layer {
  std::string_view name;
  std::vector<std::string_view> may_include;
};

const std::array<Layer, 10>& layers() {
  static const std::array<Layer, 10> table{{
      {"core", {}},
      {"material", {"core"}},
      {"mesh", {"core"}},
      {"element", {"core", "material", "mesh"}},
      {"model", {"core"}},
      {"contact", {"core", "material", "mesh", "element", "model"}},
      {"solver", {"core", "material", "mesh", "element", "model", "contact"}},
      {"io", {"core", "material", "mesh", "element", "model", "contact", "solver"}},
      {"scenarios", {"core", "material", "mesh", "element", "model", "contact", "solver", "io"}},
      {"apps", {"core", "material", "mesh", "element", "model", "contact", "solver", "io", "scenarios"}},
  }};
  return table;
}

const Layer* find_layer(std::string_view name) {
  for (const auto& l : layers())
    if (l.name == name) return &l;
  return nullptr;
}

/// The layer name of a path relative to the source root: include/slideline/<L>/..., src/<L>/...,
/// apps/... ("apps"); "" when the path is in none of them.
std::string layer_of(const fs::path& rel) {
  std::vector<std::string> parts;
  for (const auto& p : rel) parts.push_back(p.string());
  if (parts.size() >= 3 && parts[0] == "include" && parts[1] == "slideline") return parts[2];
  if (parts.size() >= 2 && parts[0] == "src") return parts[1];
  if (!parts.empty() && parts[0] == "apps") return "apps";
  return "";
}

bool is_source(const fs::path& p) {
  const auto e = p.extension().string();
  return e == ".hpp" || e == ".cpp" || e == ".h" || e == ".cc" || e == ".inl";
}

struct Checker {
  fs::path root;
  std::vector<std::string> violations;

  void report(const fs::path& rel, int line, const std::string& what) {
    violations.push_back(rel.generic_string() + ":" + std::to_string(line) + ": " + what);
  }

  /// The layer an include names, or nullopt with a violation reported.
  std::optional<std::string> target_layer(const fs::path& file, const std::string& inc, const fs::path& rel,
                                          int line) {
    if (inc.rfind("slideline/", 0) == 0) {
      const fs::path t = fs::path("include") / inc;
      if (fs::exists(root / t)) return layer_of(t);
    }
    const fs::path local = (file.parent_path() / inc).lexically_normal();
    if (fs::exists(local)) return layer_of(fs::relative(local, root));
    report(rel, line, "#include \"" + inc + "\" resolves to no file under include/, src/ or apps/");
    return std::nullopt;
  }

  void check_file(const fs::path& file) {
    const fs::path rel = fs::relative(file, root);
    const std::string from = layer_of(rel);
    const Layer* layer = find_layer(from);
    if (!layer) {
      report(rel, 0, "directory '" + from + "' has no layer (add it to the table in tests/layering/check_layers.cpp)");
      return;
    }
    static const std::regex include_re(R"(^\s*#\s*include\s*"([^"]+)\")");
    std::ifstream in(file);
    std::string text;
    int line = 0;
    while (std::getline(in, text)) {
      ++line;
      std::smatch m;
      if (!std::regex_search(text, m, include_re)) continue;
      const auto to = target_layer(file, m[1].str(), rel, line);
      if (!to || *to == from) continue;
      const auto& ok = layer->may_include;
      if (std::find(ok.begin(), ok.end(), *to) == ok.end())
        report(rel, line, "layer '" + from + "' includes \"" + m[1].str() + "\" of layer '" + *to + "'" +
                              (find_layer(*to) ? "" : " (not in the layer table)"));
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: check_layers <source root>\n";
    return 2;
  }
  Checker ck{fs::path(argv[1]).lexically_normal(), {}};
  std::vector<fs::path> files;
  for (const char* top : {"include", "src", "apps"}) {
    if (!fs::exists(ck.root / top)) continue;
    for (const auto& e : fs::recursive_directory_iterator(ck.root / top))
      if (e.is_regular_file() && is_source(e.path())) files.push_back(e.path());
  }
  if (files.empty()) {
    std::cerr << "check_layers: no sources under " << ck.root << "\n";
    return 2;
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) ck.check_file(f);
  for (const auto& v : ck.violations) std::cout << v << "\n";
  std::cout << files.size() << " files, " << ck.violations.size() << " include(s) crossing a layer the wrong way\n";
  return ck.violations.empty() ? 0 : 1;
}

// The layering of baker/'s folders (docs/design/layers.md): every `#include "baker/F/..."` in a
// source under baker/ names a folder F at or below the including file's own folder. A folder
// missing from the list below has no layer yet and fails too: give it one (here and in
// layers.md) before it lands.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

/// baker/'s folders, lowest first (docs/design/layers.md, one paragraph each).
const std::vector<std::string> kLayers = {"util",      "math",   "io",         "models", "custom",
                                          "integrate", "tables", "quantities", "bake",   "fit",
                                          "verify",    "scene",  "bench",      "atlas",  "cli"};

/// The layer index of `folder`, or -1 when it has none.
int LayerOf(const std::string& folder) {
  auto it = std::find(kLayers.begin(), kLayers.end(), folder);
  return it == kLayers.end() ? -1 : int(it - kLayers.begin());
}

/// The folder of a path under baker/ ("baker/models/brdf.h" -> "models"); "" for a file at
/// baker/'s top.
std::string FolderOf(const std::string& path) {
  const size_t a = path.find('/'), b = path.find('/', a + 1);
  return b == std::string::npos ? "" : path.substr(a + 1, b - a - 1);
}

/// One line per problem in `text`, the source at `path` (relative to the repository,
/// "baker/<folder>/<file>"): "path:line: includes baker/F/x.h, a higher layer (F above G)", or
/// the including folder or the included one has no layer.
std::vector<std::string> LayeringProblems(const std::string& path, const std::string& text) {
  std::vector<std::string> out;
  const std::string from = FolderOf(path);
  const int fromLayer = LayerOf(from);
  std::istringstream lines(text);
  std::string line;
  for (int n = 1; std::getline(lines, line); ++n) {
    const size_t hash = line.find_first_not_of(" \t");
    if (hash == std::string::npos || line.compare(hash, 1, "#") != 0) continue;
    const size_t inc = line.find("include", hash);
    const size_t open = line.find("\"baker/", hash);
    if (inc == std::string::npos || open == std::string::npos || open < inc) continue;
    const size_t close = line.find('"', open + 1);
    const std::string target = line.substr(open + 1, close - open - 1);
    const std::string to = FolderOf(target);
    const std::string where = path + ":" + std::to_string(n) + ": ";
    if (fromLayer < 0) {
      out.push_back(where + "folder baker/" + from + "/ has no layer");
      break;
    }
    const int toLayer = LayerOf(to);
    if (toLayer < 0)
      out.push_back(where + "includes " + target + ", whose folder has no layer");
    else if (toLayer > fromLayer)
      out.push_back(where + "includes " + target + ", a higher layer (" + to + " above " + from +
                    ")");
  }
  return out;
}

/// LayeringProblems of every .h, .cpp and .inc file under root/baker, sorted by path.
std::vector<std::string> TreeLayeringProblems(const std::filesystem::path& root) {
  std::vector<std::string> paths;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root / "baker")) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".h" || ext == ".cpp" || ext == ".inc"))
      paths.push_back(std::filesystem::relative(e.path(), root).generic_string());
  }
  std::sort(paths.begin(), paths.end());
  std::vector<std::string> out;
  for (const std::string& p : paths) {
    std::ifstream in(root / p);
    std::stringstream text;
    text << in.rdbuf();
    for (std::string& problem : LayeringProblems(p, text.str())) out.push_back(problem);
  }
  return out;
}

}  // namespace

TEST_CASE("An include of a higher layer is named with its file and line", "[layering]") {
  const std::string text =
      "#include <vector>\n"
      "#include \"baker/math/vec3.h\"\n"
      "#include \"kiln/table.h\"\n"
      "#include \"baker/bench/monte_carlo.h\"\n";
  const std::vector<std::string> problems = LayeringProblems("baker/quantities/albedo.cpp", text);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0] ==
        "baker/quantities/albedo.cpp:4: includes baker/bench/monte_carlo.h, a higher layer "
        "(bench above quantities)");
  // The same folder and the layers below are fine; so is a file at the folder's own layer.
  CHECK(LayeringProblems("baker/bench/x.cpp", text).empty());
  CHECK(LayeringProblems("baker/models/x.h", "#include \"baker/models/brdf.h\"\n").empty());
}

TEST_CASE("A folder without a layer is refused", "[layering]") {
  CHECK(LayeringProblems("baker/newfolder/x.cpp", "#include \"baker/math/vec3.h\"\n") ==
        std::vector<std::string>{"baker/newfolder/x.cpp:1: folder baker/newfolder/ has no layer"});
  CHECK(LayeringProblems("baker/cli/x.cpp", "#include \"baker/newfolder/x.h\"\n") ==
        std::vector<std::string>{
            "baker/cli/x.cpp:1: includes baker/newfolder/x.h, whose folder has no layer"});
}

TEST_CASE("No source under baker/ includes a higher layer", "[layering]") {
  const std::vector<std::string> problems = TreeLayeringProblems(KILN_SOURCE_DIR);
  std::string all;
  for (const std::string& p : problems) all += p + "\n";
  INFO(all);
  CHECK(problems.empty());
}

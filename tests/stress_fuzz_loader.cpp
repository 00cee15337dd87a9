// Stress: the EXR loader under mutation. A seeded loop mutates small valid kiln tables (the seeds
// of tests/fuzz_corpus/) -- bit flips, interesting bytes and integers, inserted, erased and
// duplicated chunks, truncation -- and loads every result: each must give a clean one-line error
// or a table that validates and samples to finite values, never a crash. 2000 mutants in the
// normal run, 200000 in the long one (not counting the oversized-attribute class, see below).
// Every file kept in tests/fuzz_corpus/ (the seed corpus of the libFuzzer target
// fuzz/fuzz_loader.cpp and the crashers it found) is loaded the same way. The oom-* files declare
// an attribute of ~2 GB in a 1 KB file; OpenEXR 3.1 allocates (and, for a string, zero-fills: 2 GB
// resident, 1.2 s) the declared size before it notices, so the loader walks the attribute list
// first and refuses a size the file cannot hold: they are refused from the header, in-process,
// and `kiln inspect` refuses them in a process limited to 1 GB of memory.
// known-cubic-overflow.exr is a valid table (found by the long mutation loop) whose texels reach
// 3.4e38: its cubic lookups overshoot past the largest float, and LutView::sample saturates them.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>

#include "kiln/exr_loader.h"
#include "stress_util.h"
#include "test_util.h"

using namespace kiln;
using namespace kiln::stress;

namespace {

const std::string kCorpus = std::string(KILN_SOURCE_DIR) + "/tests/fuzz_corpus";

/// Every file of tests/fuzz_corpus/, sorted; the seeds are the valid tables named seed-*.
std::vector<std::string> CorpusFiles(bool seedsOnly) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(kCorpus)) {
    std::string name = e.path().filename().string();
    if (!e.is_regular_file()) continue;
    if (!seedsOnly || name.rfind("seed-", 0) == 0) files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// True when sampling `t` at its corners, inside, outside and at NaN gives finite channels, with
/// the linear filter (and the cubic one when `cubic`).
bool SamplesFinite(const Table& t, bool cubic) {
  LutView view = t.view();
  std::vector<float> out(t.channels.size());
  for (double u : {-1.0, 0.0, 0.3, 0.5, 1.0, 2.0, std::numeric_limits<double>::quiet_NaN()}) {
    double x[3];
    for (int d = 0; d < 3; ++d) x[d] = view.axis[d].lo + (view.axis[d].hi - view.axis[d].lo) * u;
    for (Filter f : {Filter::Linear, Filter::Cubic}) {
      if (f == Filter::Cubic && !cubic) continue;
      view.sample(x, out.data(), f);
      for (float v : out)
        if (!std::isfinite(v)) return false;
    }
  }
  return true;
}

/// What the loader must do with any file: a clean refusal or a usable table. Returns "" when it
/// did, else what went wrong.
std::string CheckLoad(const std::string& path, bool* loaded = nullptr) {
  Table t;
  std::string error;
  bool ok = loadTable(path, t, error);
  if (loaded) *loaded = ok;
  if (!ok) {
    if (error.rfind("kiln: cannot load table '" + path + "': ", 0) != 0)
      return "bad message: " + error;
    if (error.find('\n') != std::string::npos) return "message on several lines: " + error;
    return "";
  }
  std::string problem;
  if (!validateTable(t, problem)) return "loaded an invalid table: " + problem;
  // Linear lookups are convex combinations of the texels: always finite. Cubic ones overshoot
  // (total weight up to ~3 per axis), so they are finite while the texels stay below 1e36.
  float largest = 0;
  for (float v : t.data) largest = std::max(largest, std::abs(v));
  if (!SamplesFinite(t, largest <= 1e36f)) return "non-finite sample";
  return "";
}

/// True when the OpenEXR header declares an attribute larger than the whole file: the oom-*
/// class of the file comment, which OpenEXR alone would allocate; the mutation loops count it
/// and require the loader to refuse it.
bool DeclaresOversizedAttribute(const std::string& b) {
  size_t p = 8;  // magic and version
  auto cstring = [&](size_t& at) {
    while (at < b.size() && b[at] != 0) ++at;
    return at < b.size() ? at++ : b.size();
  };
  for (int guard = 0; guard < 10000 && p < b.size(); ++guard) {
    size_t nameStart = p, nameEnd = cstring(p);
    if (nameEnd == b.size() || nameEnd == nameStart) return false;
    if (cstring(p) == b.size() || p + 4 > b.size()) return false;
    uint32_t declared = 0;
    for (int k = 3; k >= 0; --k) declared = declared << 8 | static_cast<unsigned char>(b[p + k]);
    p += 4;
    if (declared > b.size()) return true;
    p += declared;
  }
  return false;
}

/// One random mutation of `b` (the header, where the structure is, gets most of them).
void Mutate(std::string& b, test::Rng& rng) {
  auto below = [&](size_t n) {
    return n == 0 ? size_t(0) : static_cast<size_t>(rng.Uniform() * n) % n;
  };
  auto pos = [&] {
    return rng.Uniform() < 0.8 ? below(std::min<size_t>(b.size(), 1200)) : below(b.size());
  };
  if (b.empty()) {
    b.push_back(static_cast<char>(below(256)));
    return;
  }
  static const uint32_t kInts[] = {0,    1,      2,          3,           0x7F,        0x80,
                                   0xFF, 0xFFFF, 0x7FFFFFFF, 0x80000000u, 0xFFFFFFFFu, 1u << 30};
  switch (below(9)) {
    case 0:
      b[pos()] ^= static_cast<char>(1 << below(8));
      break;  // flip a bit
    case 1:
      b[pos()] = static_cast<char>(below(256));
      break;  // random byte
    case 2:
      b[pos()] = "\x00\x01\x7f\x80\xff"[below(5)];
      break;   // interesting byte
    case 3: {  // interesting int32
      size_t p = pos();
      uint32_t v = kInts[below(sizeof kInts / sizeof kInts[0])];
      for (int k = 0; k < 4 && p + k < b.size(); ++k) b[p + k] = static_cast<char>(v >> (8 * k));
      break;
    }
    case 4:
      b.insert(pos(), std::string(1 + below(16), static_cast<char>(below(256))));
      break;   // insert
    case 5: {  // erase
      size_t p = pos();
      b.erase(p, std::min(b.size() - p, 1 + below(32)));
      break;
    }
    case 6: {  // duplicate a chunk
      size_t p = pos(), n = std::min(b.size() - p, 1 + below(64));
      b.insert(pos(), b.substr(p, n));
      break;
    }
    case 7:
      b.resize(below(b.size()));
      break;    // truncate
    default: {  // swap two bytes
      size_t p = pos(), q = pos();
      std::swap(b[p], b[q]);
    }
  }
}

/// Loads `count` mutants (1 to 4 mutations each) of the seeds; checks every result loads cleanly
/// and every one declaring an oversized attribute is refused.
void MutationLoop(int count, uint64_t seed) {
  std::vector<std::string> seeds;
  for (const std::string& f : CorpusFiles(true)) seeds.push_back(test::ReadFile(f));
  REQUIRE(seeds.size() >= 3);
  ScratchDir dir("fuzz_" + std::to_string(seed));
  std::string path = dir / "mutant.exr";
  test::Rng rng(seed);
  int loaded = 0, failures = 0, oversized = 0;
  for (int i = 0; i < count; ++i) {
    std::string bytes = seeds[static_cast<size_t>(rng.Uniform() * seeds.size()) % seeds.size()];
    int n = 1 + static_cast<int>(rng.Uniform() * 4);
    for (int k = 0; k < n; ++k) Mutate(bytes, rng);
    bool isOversized = DeclaresOversizedAttribute(bytes);
    oversized += isOversized;
    WriteFile(path, bytes);
    bool ok = false;
    std::string problem = CheckLoad(path, &ok);
    if (isOversized && ok) problem = "a table declaring an oversized attribute was loaded";
    loaded += ok;
    if (!problem.empty()) {
      // Keep the offender next to the corpus for a look (not committed automatically).
      WriteFile(dir / ("failure-" + std::to_string(i) + ".exr"), bytes);
      std::filesystem::copy_file(
          dir / ("failure-" + std::to_string(i) + ".exr"),
          "/tmp/kiln-fuzz-failure-" + std::to_string(seed) + "-" + std::to_string(i) + ".exr",
          std::filesystem::copy_options::overwrite_existing);
      if (failures++ < 5) FAIL_CHECK("mutation " << i << ": " << problem);
    }
  }
  std::printf(
      "stress fuzz: %d mutants loaded (seed %llu): %d valid tables, %d refused cleanly (%d of them "
      "declaring an oversized attribute), %d failures\n",
      count, static_cast<unsigned long long>(seed), loaded, count - loaded - failures, oversized,
      failures);
  CHECK(failures == 0);
}

}  // namespace

TEST_CASE(
    "Every file of the fuzz corpus loads cleanly: the seeds as tables, the rest refused or valid",
    "[stress][fuzz][io]") {
  std::vector<std::string> files = CorpusFiles(false);
  REQUIRE(files.size() >= 5);
  for (const std::string& f : files) {
    bool loaded = false;
    std::string problem = CheckLoad(f, &loaded);
    INFO(f << ": " << problem);
    CHECK(problem.empty());
    if (std::filesystem::path(f).filename().string().rfind("seed-", 0) == 0) CHECK(loaded);
  }
}

namespace {

/// The oom-* files of the corpus.
std::vector<std::string> OomFiles() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(kCorpus))
    if (e.path().filename().string().rfind("oom-", 0) == 0) files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

/// Under AddressSanitizer the memory cap cannot be tested: an address-space limit starves ASan's
/// own shadow memory, and its operator new aborts on a failed allocation instead of throwing
/// std::bad_alloc (allocator_may_return_null does not change that for new[]).
constexpr bool kUnderAsan =
#if defined(__SANITIZE_ADDRESS__)
    true;
#else
    false;
#endif

/// `kiln inspect FILE` in a process limited to 1 GB of address space.
test::CommandResult InspectWithLittleMemory(const std::string& file) {
  return RunKilnFor(120, "inspect " + Quote(file), "ulimit -v 1048576;");
}

}  // namespace

TEST_CASE(
    "A file declaring a 2 GB attribute is refused cleanly by kiln inspect, even with 1 GB of "
    "memory",
    "[stress][fuzz][io][cli]") {
  std::vector<std::string> files = OomFiles();
  REQUIRE(files.size() >= 2);
  if (kUnderAsan) {
    WARN("skipped under AddressSanitizer (see kUnderAsan)");
    return;
  }
  for (const std::string& f : files) {
    auto r = InspectWithLittleMemory(f);
    INFO(f << ": exit " << r.exitCode << ", stderr: " << r.err);
    CHECK(IsCleanRefusal(r));
    CHECK(r.err.find(f) != std::string::npos);
  }
}

TEST_CASE("A file declaring a 2 GB attribute is refused from its header, without the allocation",
          "[stress][fuzz][io]") {
  for (const std::string& f : OomFiles()) {
    Table t;
    std::string error;
    CHECK_FALSE(loadTable(f, t, error));
    INFO(f << ": " << error);
    CHECK(error.find(f) != std::string::npos);
    CHECK(error.find("bad_alloc") == std::string::npos);
    if (f.find("scanline") == std::string::npos) CHECK(error.find("declares") != std::string::npos);
  }
}

TEST_CASE("Cubic lookups of a valid table with texels near the largest float stay finite",
          "[stress][fuzz][io]") {
  Table t = loadTable(kCorpus + "/known-cubic-overflow.exr");
  CHECK(SamplesFinite(t, false));
  CHECK(SamplesFinite(t, true));
}

TEST_CASE("2000 mutations of valid kiln tables: clean errors or valid tables, never a crash",
          "[stress][fuzz][io]") {
  MutationLoop(2000, 20240601);
}

TEST_CASE("200000 mutations of valid kiln tables", "[stress][fuzz][io][long]") {
  MutationLoop(200000, 777);
}

// baker/io/bounded_json.h: the one place kiln parses JSON it reads from a file (manifest.json,
// the kiln.json of a KTX2 or PNG table, a DDS table's manifest entry, scene files and glTF),
// with a limit on nesting: a document nested deeper than kMaxJsonDepth is refused before it is
// parsed, so neither the parser's memory nor the recursion of whoever copies, prints or walks the
// document grows with a hostile file. Also a cache of parsed files keyed by their identity, so
// that a run reading one large manifest for many tables parses it once.
#pragma once
#include <cstddef>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace kiln {

/// The deepest nesting of arrays and objects kiln reads (its own files need 4; glTF about 8).
constexpr std::size_t kMaxJsonDepth = 64;

/// How many parsed files ReadJsonFileCached keeps (a bake reads one manifest, a scene a few).
constexpr std::size_t kJsonCacheFiles = 4;

/// Why a JSON text was refused: `what()` is one line without the file's name, e.g. "nested
/// deeper than 64 levels (line 1, column 65)" or "not valid JSON (syntax error ...)"; `offset` is
/// the byte where the problem was found (0 when unknown).
struct JsonTextError : std::runtime_error {
  JsonTextError(const std::string& message, std::size_t at)
      : std::runtime_error(message), offset(at) {}
  std::size_t offset;
};

/// The offset of the first '[' or '{' (outside strings) that opens nesting level
/// `maxDepth` + 1, or std::string::npos when the text is nested no deeper than `maxDepth`.
/// One pass over the bytes, no allocation; the text need not be valid JSON.
std::size_t JsonTooDeepAt(const std::string& text, std::size_t maxDepth = kMaxJsonDepth);

/// "line L, column C" of text[offset] (0-based offset; 1-based line and column).
std::string JsonLineColumn(const std::string& text, std::size_t offset);

/// nlohmann's exception message without its "[json.exception.xxx.nnn] " head, on one line.
std::string JsonErrorDetail(const std::string& what);

/// Parses `text` (nested at most kMaxJsonDepth deep). Throws JsonTextError: "nested deeper than
/// 64 levels (line L, column C)" or "not valid JSON (<nlohmann's reason>)".
nlohmann::ordered_json ParseBoundedJson(const std::string& text);

/// The parsed contents of the JSON file at `path` (ParseBoundedJson), shared with every earlier
/// call for the same path while the file is the same one: same device, inode, size, modification
/// and change times (to the nanosecond), and, while its modification time is less than 2 s old
/// (a file rewritten within one tick of the file system's clock keeps its times), the same bytes
/// (read again and hashed). A run that reads one manifest for every table parses it once.
/// Throws std::runtime_error "cannot read <path>: <strerror>" when it cannot be read and
/// JsonTextError (ParseBoundedJson's, without the path) when it is refused. Keeps the last
/// kJsonCacheFiles files. Thread-safe. Each parse writes the test note "parsing '<path>'"
/// (TestNote, test_hooks.h: only with KILN_TEST_NOTES set).
std::shared_ptr<const nlohmann::ordered_json> ReadJsonFileCached(const std::string& path);

/// Tells the cache of ReadJsonFileCached that the file at `path`, as it is now, holds `text`,
/// parsed as `doc`: a writer that has just renamed the file into place (under the folder's lock)
/// saves the next reader from parsing back what it wrote. Does nothing when `path` cannot be
/// stat'ed.
void RememberJsonFile(const std::string& path, const std::string& text,
                      std::shared_ptr<const nlohmann::ordered_json> doc);

}  // namespace kiln

// Typed access to a scene file's JSON that names the place of every problem: each accessor
// takes the JSON pointer of the value it reads and throws SceneError with it.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "baker/io/bounded_json.h"
#include "baker/scene/scene_error.h"

namespace kiln {

using Json = nlohmann::json;

/// The JSON pointer of child `token` (a key, escaped per RFC 6901) or `index` of `parent`.
std::string PointerChild(const std::string& parent, const std::string& token);
std::string PointerChild(const std::string& parent, size_t index);

/// The largest scene file ReadSceneFile reads (a larger glb: its JSON chunk, up to this size).
constexpr size_t kMaxSceneBytes = size_t{64} << 20;
/// The deepest nesting of arrays and objects ParseSceneJson accepts (glTF needs about 8): the
/// limit of every JSON kiln reads (bounded_json.h).
constexpr size_t kMaxSceneDepth = kMaxJsonDepth;

/// Parses `text` as JSON; a syntax error throws SceneError at "line L, column C" (`prefix` goes
/// before it, e.g. "JSON chunk, " for a glb), and so does nesting deeper than kMaxSceneDepth.
Json ParseSceneJson(const std::string& text, const std::string& file,
                    const std::string& prefix = "");

/// Reads the whole file, at most kMaxSceneBytes (a bounded read: a device or a pipe that never
/// ends is refused at the cap); throws SceneError when it cannot.
std::string ReadSceneFile(const std::string& path);

/// Accessors for one file. `at` is always the pointer of the value passed in.
struct JsonReader {
  std::string file;

  [[noreturn]] void Fail(const std::string& at, const std::string& problem) const;

  /// Checks the kind of a value ("an object", "an array", ...).
  const Json& Object(const Json& v, const std::string& at) const;
  const Json& Array(const Json& v, const std::string& at) const;
  double Number(const Json& v, const std::string& at) const;
  std::string String(const Json& v, const std::string& at) const;
  /// A non-negative integer below `count` that refers to one of `count` `what`s.
  size_t Index(const Json& v, const std::string& at, size_t count, const std::string& what) const;

  /// obj[key] or nullptr when absent (obj must be an object).
  static const Json* Find(const Json& obj, const std::string& key);
  /// obj[key] as a number in [lo, hi], or `def` when absent.
  double NumberIn(const Json& obj, const std::string& at, const std::string& key, double def,
                  double lo, double hi) const;
  /// obj[key] as an array (empty when absent).
  const Json& ArrayOrEmpty(const Json& obj, const std::string& at, const std::string& key) const;
};

/// The name of a JSON value's type for messages: "a string", "an object", ...
std::string JsonKind(const Json& v);

/// %g with up to 6 significant digits ("0.3", "1.5", "1e-05"): for table names.
std::string ShortNumber(double x);
/// The shortest %g that reads back as x: for messages and reports.
std::string ExactNumber(double x);

}  // namespace kiln

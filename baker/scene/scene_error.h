// The one error a scene reader throws: a file kiln cannot use, with the place in it.
#pragma once
#include <stdexcept>
#include <string>

namespace kiln {

/// A bad scene file. what() is one line, "FILE: PLACE: PROBLEM", where PLACE is a JSON pointer
/// (RFC 6901, e.g. "/materials/3/pbrMetallicRoughness/roughnessFactor"), "line L, column C" for
/// a JSON syntax error, or "byte N (...)" in a glb container.
class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& file, const std::string& place, const std::string& problem)
      : std::runtime_error(file + ": " + (place.empty() ? "" : place + ": ") + problem),
        file_(file),
        place_(place) {}
  const std::string& File() const { return file_; }
  const std::string& Place() const { return place_; }

 private:
  std::string file_, place_;
};

}  // namespace kiln

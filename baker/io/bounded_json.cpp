// JSON parsing with a nesting limit, and the cache of parsed files (baker/io/bounded_json.h).
#include "baker/io/bounded_json.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <deque>
#include <fstream>
#include <mutex>
#include <sstream>

#include "baker/io/test_hooks.h"

namespace kiln {

std::size_t JsonTooDeepAt(const std::string& text, std::size_t maxDepth) {
  std::size_t depth = 0;
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > maxDepth) return i;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return std::string::npos;
}

std::string JsonLineColumn(const std::string& text, std::size_t offset) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

std::string JsonErrorDetail(const std::string& what) {
  const std::size_t head =
      what.rfind("[json.exception.", 0) == 0 ? what.find("] ") : std::string::npos;
  std::string detail = head == std::string::npos ? what : what.substr(head + 2);
  for (char& c : detail)
    if (c == '\n' || c == '\r') c = ' ';
  return detail;
}

nlohmann::ordered_json ParseBoundedJson(const std::string& text) {
  const std::size_t deep = JsonTooDeepAt(text);
  if (deep != std::string::npos)
    throw JsonTextError("nested deeper than " + std::to_string(kMaxJsonDepth) + " levels (" +
                            JsonLineColumn(text, deep) + ")",
                        deep);
  try {
    return nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::ordered_json::parse_error& e) {
    throw JsonTextError("not valid JSON (" + JsonErrorDetail(e.what()) + ")",
                        e.byte == 0 ? 0 : static_cast<std::size_t>(e.byte - 1));
  } catch (const nlohmann::ordered_json::exception& e) {
    throw JsonTextError("not valid JSON (" + JsonErrorDetail(e.what()) + ")", 0);
  }
}

namespace {

/// What identifies one version of a file: replaced (renamed over) or rewritten in place, it
/// changes.
struct FileStamp {
  dev_t device = 0;
  ino_t inode = 0;
  off_t size = 0;
  struct timespec modified {
  }, changed{};
  bool operator==(const FileStamp& o) const {
    return device == o.device && inode == o.inode && size == o.size &&
           modified.tv_sec == o.modified.tv_sec && modified.tv_nsec == o.modified.tv_nsec &&
           changed.tv_sec == o.changed.tv_sec && changed.tv_nsec == o.changed.tv_nsec;
  }
};

FileStamp StampOf(const struct stat& st) {
  FileStamp s;
  s.device = st.st_dev;
  s.inode = st.st_ino;
  s.size = st.st_size;
  s.modified = st.st_mtim;
  s.changed = st.st_ctim;
  return s;
}

struct CachedFile {
  std::string path;
  FileStamp stamp;
  std::shared_ptr<const nlohmann::ordered_json> doc;
};

std::mutex g_cacheMutex;
std::deque<CachedFile> g_cache;  // newest first

void Remember(const std::string& path, const FileStamp& stamp,
              std::shared_ptr<const nlohmann::ordered_json> doc) {
  std::lock_guard<std::mutex> lock(g_cacheMutex);
  for (auto it = g_cache.begin(); it != g_cache.end(); ++it)
    if (it->path == path) {
      g_cache.erase(it);
      break;
    }
  g_cache.push_front({path, stamp, std::move(doc)});
  if (g_cache.size() > kJsonCacheFiles) g_cache.pop_back();
}

}  // namespace

std::shared_ptr<const nlohmann::ordered_json> ReadJsonFileCached(const std::string& path) {
  auto cannotRead = [&](int error) {
    return std::runtime_error("cannot read " + path + ": " + std::strerror(error));
  };
  struct stat before {};
  if (stat(path.c_str(), &before) != 0) throw cannotRead(errno);
  if (!S_ISREG(before.st_mode))
    throw std::runtime_error("cannot read " + path + ": not a regular file");
  {
    std::lock_guard<std::mutex> lock(g_cacheMutex);
    for (const CachedFile& c : g_cache)
      if (c.path == path && c.stamp == StampOf(before)) return c.doc;
  }
  TestNote("parsing '" + path + "'");  // tests count the parses of a run
  std::ifstream in(path, std::ios::binary);
  if (!in) throw cannotRead(errno);
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw cannotRead(errno ? errno : EIO);
  auto doc = std::make_shared<const nlohmann::ordered_json>(ParseBoundedJson(text.str()));
  // Remembered only when the file did not change while it was read.
  struct stat after {};
  if (stat(path.c_str(), &after) == 0 && StampOf(after) == StampOf(before))
    Remember(path, StampOf(after), doc);
  return doc;
}

void RememberJsonFile(const std::string& path, std::shared_ptr<const nlohmann::ordered_json> doc) {
  struct stat st {};
  if (stat(path.c_str(), &st) == 0) Remember(path, StampOf(st), std::move(doc));
}

}  // namespace kiln

// JSON parsing with a nesting limit, and the cache of parsed files (baker/io/bounded_json.h).
#include "baker/io/bounded_json.h"

#include <sys/stat.h>

#include <time.h>

#include <cerrno>
#include <cstring>
#include <deque>
#include <functional>
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

/// How long after its modification time a file's stamp is not proof that it is unchanged: a file
/// rewritten in place within one tick of the file system's clock (a jiffy; 2 s on FAT, 1 s on
/// some network file systems) keeps its size and times.
constexpr double kRacySeconds = 2.0;

/// True when `stamp`'s modification time is less than kRacySeconds before now.
bool Racy(const FileStamp& stamp) {
  struct timespec now {};
  clock_gettime(CLOCK_REALTIME, &now);
  const double age = double(now.tv_sec - stamp.modified.tv_sec) +
                     1e-9 * double(now.tv_nsec - stamp.modified.tv_nsec);
  return age < kRacySeconds;
}

std::size_t TextHash(const std::string& text) { return std::hash<std::string>{}(text); }

struct CachedFile {
  std::string path;
  FileStamp stamp;
  std::size_t textHash = 0;  ///< of the bytes the document was parsed from
  bool racy = false;         ///< Racy(stamp) when last checked: the bytes are compared again
  std::shared_ptr<const nlohmann::ordered_json> doc;
};

std::mutex g_cacheMutex;
std::deque<CachedFile> g_cache;  // newest first

void Remember(const std::string& path, const FileStamp& stamp, std::size_t textHash,
              std::shared_ptr<const nlohmann::ordered_json> doc) {
  std::lock_guard<std::mutex> lock(g_cacheMutex);
  for (auto it = g_cache.begin(); it != g_cache.end(); ++it)
    if (it->path == path) {
      g_cache.erase(it);
      break;
    }
  g_cache.push_front({path, stamp, textHash, Racy(stamp), std::move(doc)});
  if (g_cache.size() > kJsonCacheFiles) g_cache.pop_back();
}

/// The whole file at `path`; throws as ReadJsonFileCached.
std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad())
    throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno ? errno : EIO));
  return text.str();
}

}  // namespace

std::shared_ptr<const nlohmann::ordered_json> ReadJsonFileCached(const std::string& path) {
  struct stat before {};
  if (stat(path.c_str(), &before) != 0)
    throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  if (!S_ISREG(before.st_mode))
    throw std::runtime_error("cannot read " + path + ": not a regular file");
  const FileStamp stamp = StampOf(before);
  std::string text;
  bool haveText = false;
  {
    std::lock_guard<std::mutex> lock(g_cacheMutex);
    for (CachedFile& c : g_cache) {
      if (c.path != path || !(c.stamp == stamp)) continue;
      if (!c.racy) return c.doc;
      // Modified too recently for its stamp to prove anything: compare the bytes (a read and a
      // hash, far cheaper than a parse).
      text = ReadText(path);
      haveText = true;
      if (TextHash(text) == c.textHash) {
        c.racy = Racy(stamp);
        return c.doc;
      }
    }
  }
  TestNote("parsing '" + path + "'");  // tests count the parses of a run
  if (!haveText) text = ReadText(path);
  auto doc = std::make_shared<const nlohmann::ordered_json>(ParseBoundedJson(text));
  // Remembered only when the file did not change while it was read.
  struct stat after {};
  if (stat(path.c_str(), &after) == 0 && StampOf(after) == stamp)
    Remember(path, stamp, TextHash(text), doc);
  return doc;
}

void RememberJsonFile(const std::string& path, const std::string& text,
                      std::shared_ptr<const nlohmann::ordered_json> doc) {
  struct stat st {};
  if (stat(path.c_str(), &st) == 0) Remember(path, StampOf(st), TextHash(text), std::move(doc));
}

}  // namespace kiln

// The files a verify path names (verify.h, VerifyInputs).
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "baker/verify/verify.h"

namespace kiln::verify {
namespace {

/// Whether the EXR file at `path` is part 2 or later of a wider table (kiln.part > 1): loading
/// part 1 reads the whole table, so a folder's listing names the table once. False for a file
/// whose header does not read (its own line reports it).
bool IsLaterPart(const std::string& path) {
  try {
    Imf::InputFile in(path.c_str(), 1);
    const auto* part = in.header().findTypedAttribute<Imf::IntAttribute>("kiln.part");
    return part != nullptr && part->value() > 1;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

std::vector<std::string> VerifyInputs(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) {
    if (errno == ENOENT || errno == ENOTDIR)
      throw std::invalid_argument("verify: no such file or folder '" + path + "'");
    throw std::invalid_argument("verify: cannot access '" + path + "' (" + std::strerror(errno) +
                                ")");
  }
  if (!S_ISDIR(st.st_mode)) return {path};
  std::vector<std::string> out;
  if (DIR* d = opendir(path.c_str())) {
    while (dirent* e = readdir(d)) {
      std::string n = e->d_name;
      if (n.size() > 4 && n.compare(n.size() - 4, 4, ".exr") == 0 && !IsLaterPart(path + "/" + n))
        out.push_back(path + "/" + n);
    }
    closedir(d);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace kiln::verify

// The committed catalogue in luts/, as the tests that read every shipped table list it.
#pragma once
#include <dirent.h>

#include <algorithm>
#include <string>
#include <vector>

namespace kiln::test {

/// The repository's luts/ folder.
inline std::string LutsDir() { return std::string(KILN_SOURCE_DIR) + "/luts"; }

/// The file names of every .exr in luts/ (each part of a parted table counts), sorted.
inline std::vector<std::string> LutFiles() {
  std::vector<std::string> out;
  if (DIR* d = opendir(LutsDir().c_str())) {
    while (dirent* e = readdir(d)) {
      std::string n = e->d_name;
      if (n.size() > 4 && n.compare(n.size() - 4, 4, ".exr") == 0) out.push_back(n);
    }
    closedir(d);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace kiln::test

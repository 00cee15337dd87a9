// Write-to-temporary-and-rename.
#include "baker/io/atomic_write.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "baker/io/test_hooks.h"

namespace kiln {

namespace {

std::string oneLine(std::string text) {
    for (char& ch : text)
        if (ch == '\n' || ch == '\r') ch = ' ';
    return text;
}

}  // namespace

std::string temporaryPathFor(const std::string& path) { return path + ".tmp"; }

void writeAtomically(const std::string& path,
                     const std::function<void(const std::string& temporaryPath)>& write) {
    const std::string temporary = temporaryPathFor(path);
    std::string reason;
    try {
        write(temporary);
        const std::string name = path.substr(path.find_last_of('/') + 1);
        if (TestPauseBeforeRename(name)) TestPause("before renaming '" + temporary + "'");
        if (std::rename(temporary.c_str(), path.c_str()) != 0)
            reason = "cannot rename '" + temporary + "' into place: " + std::strerror(errno);
    } catch (const std::exception& e) {
        reason = e.what();
    } catch (...) {
        reason = "unknown error";
    }
    if (reason.empty()) return;
    std::remove(temporary.c_str());
    throw std::runtime_error(oneLine("kiln: cannot write '" + path + "': " + reason));
}

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream stream(path, std::ios::binary | std::ios::trunc);
    if (!stream) throw std::runtime_error("cannot create '" + path + "': " + std::strerror(errno));
    stream.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    stream.close();
    if (!stream) throw std::runtime_error("error while writing '" + path + "'");
}

}  // namespace kiln

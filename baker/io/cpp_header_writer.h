// baker/io/cpp_header_writer.h: embeds a kiln table in a C++ header.
#pragma once

#include <string>

#include "kiln/table.h"

namespace kiln {

class PendingFile;

/// The C++ identifier the header writer uses for a table name: every
/// character outside [A-Za-z0-9_] becomes '_', runs of '_' collapse, a
/// leading digit or '_' (or an empty name) gets the prefix "t_", and a C++
/// keyword gets a trailing '_' ("ggx-dfg" -> "ggx_dfg").
std::string cppIdentifier(const std::string& tableName);

/// The text of a self-contained C++17 header embedding `table`: its metadata
/// as constexpr values and its texels as `inline constexpr float kData[]`
/// (printed with %.9g, which round-trips every float exactly), in namespace
/// kiln::baked::<cppIdentifier(table.name)>, plus
/// `inline constexpr kiln::LutView kLut` over that data. The header needs
/// only <kiln/lut.h> (no OpenEXR). Throws std::runtime_error when the table
/// fails validateTable.
std::string cppHeaderText(const Table& table);

/// Writes cppHeaderText(table) to `path` through a temporary file and a
/// rename (see writeAtomically); throws std::runtime_error with a one-line
/// message on failure.
void writeCppHeader(const std::string& path, const Table& table);

/// Writes cppHeaderText(table) into `file`'s temporary file, without the
/// rename (the caller commits it, PendingFile::CommitAll); throws like
/// writeCppHeader.
void writeCppHeader(PendingFile& file, const Table& table);

}  // namespace kiln

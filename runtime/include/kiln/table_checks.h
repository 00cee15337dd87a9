// kiln/table_checks.h: the header checks every reader of a table file shares (the EXR loader,
// and the baker's KTX2, DDS and 16-bit PNG readers): what a file may declare before any texel is
// allocated for it.
#pragma once

#include <string>

#include "kiln/table.h"

namespace kiln {

/// The largest |lo| and |hi| of an axis: every kiln axis is a cosine, a roughness, an index of
/// refraction or an extinction coefficient, far below it.
constexpr double kMaxAxisMagnitude = 1e6;

/// The most values (nodes x channels) a table may hold: 2^30 (4 GiB of floats).
constexpr unsigned long long kMaxTableValues = 1ull << 30;

/// Why a file declaring format version `version` cannot be read ("format version 2, this runtime
/// reads 1"), or "" when `version` is kFormatVersion.
std::string formatVersionProblem(long long version);

/// The checks of everything but the texels, made by every reader of a table file before it
/// allocates any texel, and by validateTable: 1..3 axes, each with a non-empty name, valid
/// (axisProblem), with lo and hi within +-kMaxAxisMagnitude and a finite hi - lo, a layer or
/// split warp only where it may be; at most kMaxTableValues values; at least one channel, channel
/// names non-empty, unique and free of ','; channel meanings either empty or one per channel and
/// free of ';'. Returns "" when `header` passes, else a one-line description of the first problem
/// ("axis 0 ('mu'): lo -1e+308 or hi 1e+308 is beyond +-1e6, where no kiln axis reaches").
std::string tableHeaderProblem(const Table& header);

}  // namespace kiln

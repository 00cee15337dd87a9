// Consistency checks and list helpers for kiln::Table.
#include "kiln/table.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>
#include <stdexcept>

#include "kiln/table_checks.h"

namespace kiln {

namespace {
/// Upper bound on the values of a table (kMaxTableValues); keeps every index and the image
/// height within int and rejects absurd headers early.
constexpr std::uint64_t kMaxValues = kMaxTableValues;
/// A number printed with enough digits to tell close bounds apart.
std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

/// x with %.17g.
std::string numberText(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

/// Why a valid axis is still absurd (lo or hi beyond kMaxAxisMagnitude, or hi - lo not finite,
/// which would make every lookup and every verification point overflow); "" when it is not.
std::string axisRangeProblem(const Axis& axis) {
  if (!(std::fabs(axis.lo) <= kMaxAxisMagnitude && std::fabs(axis.hi) <= kMaxAxisMagnitude))
    return "lo " + numberText(axis.lo) + " or hi " + numberText(axis.hi) +
           " is beyond +-1e6, where no kiln axis reaches";
  if (!std::isfinite(axis.hi - axis.lo)) return "hi - lo is not finite";
  return "";
}

}  // namespace

std::string axisProblem(const Axis& axis) {
  if (axis.size < 1) return "size is " + std::to_string(axis.size) + ", must be >= 1";
  if (!std::isfinite(axis.lo) || !std::isfinite(axis.hi))
    return "bounds lo " + number(axis.lo) + ", hi " + number(axis.hi) + " are not finite";
  if (!(axis.lo < axis.hi)) return "lo " + number(axis.lo) + " >= hi " + number(axis.hi);
  if (axis.warp == Warp::Log && !(axis.lo > 0.0))
    return "lo " + number(axis.lo) + " <= 0 with the log warp";
  if (axis.warp == Warp::Root4LayerSplit && !axis.valid())
    return "size " + std::to_string(axis.size) +
           " with the root4-layer-split warp: needs size >= 9 and (size - 1) % 8 == 0";
  if (axis.warp == Warp::Root4LayerSplit2 && !axis.valid() && !axis.hasConstantSplit())
    return "size " + std::to_string(axis.size) +
           " with the root4-layer-split2 warp: needs size >= 33 and (size - 1) % 32 == 0";
  if (axis.hasConstantSplit() && axis.warp != Warp::Root4LayerSplit)
    return std::string("a split point ") + number(axis.split) + " on the " + warpName(axis.warp) +
           " warp (only root4-layer-split takes one)";
  if (std::isinf(axis.split) ||
      (axis.hasConstantSplit() && !(axis.lo < axis.split && axis.split < axis.hi)))
    return "split point " + number(axis.split) + " is not inside (lo " + number(axis.lo) + ", hi " +
           number(axis.hi) + ")";
  Warp parsed;
  if (!warpFromName(warpName(axis.warp), parsed)) return "unknown warp";
  return std::string();
}

std::vector<std::string> splitList(const std::string& text, char separator) {
  std::vector<std::string> items;
  if (text.empty()) return items;
  std::string::size_type start = 0;
  for (;;) {
    const std::string::size_type end = text.find(separator, start);
    if (end == std::string::npos) {
      items.push_back(text.substr(start));
      return items;
    }
    items.push_back(text.substr(start, end - start));
    start = end + 1;
  }
}

int tablePartCount(std::size_t channels) {
  if (channels <= static_cast<std::size_t>(kMaxChannelsPerFile)) return 1;
  return static_cast<int>((channels + kMaxChannelsPerFile - 1) / kMaxChannelsPerFile);
}

Table tablePart(const Table& table, int index) {
  const std::size_t nc = table.channels.size();
  const int count = tablePartCount(nc);
  if (index < 1 || index > count)
    throw std::invalid_argument("part " + std::to_string(index) + " of a table of " +
                                std::to_string(count) + " parts");
  const std::size_t first = static_cast<std::size_t>(index - 1) * kMaxChannelsPerFile;
  const std::size_t last = std::min(nc, first + kMaxChannelsPerFile);
  Table out = table;
  out.channels.assign(table.channels.begin() + first, table.channels.begin() + last);
  if (table.channelMeanings.size() == nc)
    out.channelMeanings.assign(table.channelMeanings.begin() + first,
                               table.channelMeanings.begin() + last);
  out.part = TablePart{index, count, table.channels};
  out.data.clear();
  if (!table.data.empty()) {
    const std::size_t texels = table.data.size() / nc;
    out.data.reserve(texels * (last - first));
    for (std::size_t t = 0; t < texels; ++t)
      for (std::size_t c = first; c < last; ++c) out.data.push_back(table.data[t * nc + c]);
  }
  return out;
}

namespace {
/// Whether two axes are the same grid (name, range, size, warp, constant split).
bool sameAxis(const TableAxis& a, const TableAxis& b) {
  const bool sameSplit = a.axis.hasConstantSplit() == b.axis.hasConstantSplit() &&
                         (!a.axis.hasConstantSplit() || a.axis.split == b.axis.split);
  return a.name == b.name && a.axis.lo == b.axis.lo && a.axis.hi == b.axis.hi &&
         a.axis.size == b.axis.size && a.axis.warp == b.axis.warp && sameSplit;
}
}  // namespace

Table mergeTableParts(const std::vector<Table>& parts) {
  if (parts.empty()) throw std::invalid_argument("no parts to merge");
  const Table& head = parts.front();
  const int count = head.part.count;
  if (count < 2 || static_cast<int>(parts.size()) != count)
    throw std::invalid_argument(std::to_string(parts.size()) + " parts of a table of " +
                                std::to_string(count));
  std::vector<const Table*> byIndex(static_cast<std::size_t>(count), nullptr);
  for (const Table& p : parts) {
    const std::string which = "part " + std::to_string(p.part.index) + " of '" + p.name + "'";
    if (p.part.count != count || p.part.index < 1 || p.part.index > count ||
        byIndex[static_cast<std::size_t>(p.part.index - 1)] != nullptr)
      throw std::invalid_argument(which + " does not belong to a set of " + std::to_string(count) +
                                  " distinct parts");
    bool sameAxes = p.axes.size() == head.axes.size();
    for (std::size_t d = 0; sameAxes && d < p.axes.size(); ++d)
      sameAxes = sameAxis(p.axes[d], head.axes[d]);
    if (p.name != head.name || p.specHash != head.specHash || !sameAxes ||
        p.part.tableChannels != head.part.tableChannels)
      throw std::invalid_argument(which + " differs from part " + std::to_string(head.part.index) +
                                  " in name, spec hash, axes or table channels");
    byIndex[static_cast<std::size_t>(p.part.index - 1)] = &p;
  }
  Table out = head;
  out.part = TablePart{};
  out.channels.clear();
  out.channelMeanings.clear();
  bool meanings = true;
  for (const Table* p : byIndex) {
    out.channels.insert(out.channels.end(), p->channels.begin(), p->channels.end());
    meanings = meanings && p->channelMeanings.size() == p->channels.size();
    out.channelMeanings.insert(out.channelMeanings.end(), p->channelMeanings.begin(),
                               p->channelMeanings.end());
  }
  if (!meanings) out.channelMeanings.clear();
  if (out.channels != head.part.tableChannels)
    throw std::invalid_argument("the parts of '" + head.name + "' hold channels '" +
                                joinList(out.channels, ',') + "', the table declares '" +
                                joinList(head.part.tableChannels, ',') + "'");
  const std::size_t nc = out.channels.size();
  const std::size_t texels = head.data.size() / std::max<std::size_t>(1, head.channels.size());
  out.data.assign(texels * nc, 0.0f);
  std::size_t first = 0;
  for (const Table* p : byIndex) {
    const std::size_t pc = p->channels.size();
    if (p->data.size() != texels * pc)
      throw std::invalid_argument("part " + std::to_string(p->part.index) + " of '" + head.name +
                                  "' holds " + std::to_string(p->data.size()) + " values, " +
                                  std::to_string(texels * pc) + " expected");
    for (std::size_t t = 0; t < texels; ++t)
      for (std::size_t c = 0; c < pc; ++c) out.data[t * nc + first + c] = p->data[t * pc + c];
    first += pc;
  }
  return out;
}

namespace {
/// The position of the extension's dot in the last path component (npos: none).
std::size_t extensionDot(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path.size();
  return dot;
}
}  // namespace

std::string tablePartPath(const std::string& path, int index, int count) {
  if (count <= 1) return path;
  const std::size_t dot = extensionDot(path);
  return path.substr(0, dot) + "-" + std::to_string(index) + path.substr(dot);
}

std::string tableSiblingPartPath(const std::string& path, int index, int other) {
  const std::size_t dot = extensionDot(path);
  const std::string suffix = "-" + std::to_string(index);
  if (dot < suffix.size() || path.compare(dot - suffix.size(), suffix.size(), suffix) != 0)
    throw std::invalid_argument("part " + std::to_string(index) +
                                " of a table: its file name must end in '" + suffix +
                                "' before the extension, to find the other parts");
  return path.substr(0, dot - suffix.size()) + "-" + std::to_string(other) + path.substr(dot);
}

std::string joinList(const std::vector<std::string>& items, char separator) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) text += separator;
    text += items[i];
  }
  return text;
}

namespace {

/// Why axis d of `table` cannot be read, "" when it can (tableHeaderProblem).
std::string axisHeaderProblem(const Table& table, int d) {
  const int dims = table.dims();
  const TableAxis& a = table.axes[static_cast<std::size_t>(d)];
  const std::string label = "axis " + std::to_string(d) + " ('" + a.name + "')";
  if (a.name.empty()) return "axis " + std::to_string(d) + " has no name";
  std::string axisIssue = axisProblem(a.axis);
  if (axisIssue.empty()) axisIssue = axisRangeProblem(a.axis);
  if (!axisIssue.empty()) return label + ": " + axisIssue;
  if (isLayerWarp(a.axis.warp) && (d != 0 || dims < 2))
    return label + ": the " + warpName(a.axis.warp) +
           " warp couples axis 0 to axis 1; it is allowed "
           "only on axis 0 of a table with two or more axes";
  if (a.axis.warp == Warp::Root4LayerSplit2 && dims != 3)
    return label +
           ": the root4-layer-split2 warp reads axes 1 and 2; it is allowed only on axis 0 "
           "of a table with three axes";
  if (a.axis.warp == Warp::Root4LayerSplit && dims != 3 && !a.axis.hasConstantSplit())
    return label +
           ": the root4-layer-split warp without a constant split reads axes 1 and 2; it "
           "is allowed only on axis 0 of a table with three axes";
  return "";
}

}  // namespace

std::string formatVersionProblem(long long version) {
  if (version == kFormatVersion) return "";
  return "format version " + std::to_string(version) + ", this runtime reads " +
         std::to_string(kFormatVersion);
}

std::string tableHeaderProblem(const Table& table) {
  const int dims = table.dims();
  if (dims < 1 || dims > 3) return "dims is " + std::to_string(dims) + ", must be 1, 2 or 3";
  std::uint64_t nodes = 1;
  for (int d = 0; d < dims; ++d) {
    const std::string axisIssue = axisHeaderProblem(table, d);
    if (!axisIssue.empty()) return axisIssue;
    nodes *= static_cast<std::uint64_t>(table.axes[static_cast<std::size_t>(d)].axis.size);
    if (nodes > kMaxValues) return "the grid is too large (more than 2^30 nodes)";
  }
  if (table.channels.empty()) return "the table has no channels";
  std::set<std::string> seen;
  for (const std::string& c : table.channels) {
    if (c.empty() || c.find(',') != std::string::npos)
      return "channel name '" + c + "' is empty or contains ','";
    if (!seen.insert(c).second) return "channel name '" + c + "' appears twice";
  }
  if (!table.channelMeanings.empty() && table.channelMeanings.size() != table.channels.size())
    return std::to_string(table.channelMeanings.size()) + " channel meanings for " +
           std::to_string(table.channels.size()) + " channels";
  for (const std::string& m : table.channelMeanings)
    if (m.find(';') != std::string::npos) return "channel meaning '" + m + "' contains ';'";
  if (nodes * table.channels.size() > kMaxValues)
    return "the table is too large (more than 2^30 values)";
  return "";
}

bool validateTable(const Table& table, std::string& problem) {
  problem = tableHeaderProblem(table);
  if (!problem.empty()) return false;
  std::uint64_t expected = table.channels.size();
  for (int d = 0; d < table.dims(); ++d) expected *= static_cast<std::uint64_t>(table.size(d));
  if (table.data.size() != expected) {
    problem = "data holds " + std::to_string(table.data.size()) + " values, the grid needs " +
              std::to_string(expected);
    return false;
  }
  const LutView view = table.view();
  for (std::size_t k = 0; k < table.data.size(); ++k) {
    if (!std::isfinite(table.data[k])) {
      const std::size_t channel = k % table.channels.size();
      std::size_t node = k / table.channels.size();
      const std::size_t i0 = node % static_cast<std::size_t>(view.size(0));
      node /= static_cast<std::size_t>(view.size(0));
      const std::size_t i1 = node % static_cast<std::size_t>(view.size(1));
      const std::size_t i2 = node / static_cast<std::size_t>(view.size(1));
      problem = std::string(std::isnan(table.data[k]) ? "NaN" : "infinite") + " texel at node (" +
                std::to_string(i0) + ", " + std::to_string(i1) + ", " + std::to_string(i2) +
                ") of channel '" + table.channels[channel] + "'";
      return false;
    }
  }
  return true;
}

}  // namespace kiln

#include "baker/bench/bench_csv.h"

#include <cstdio>

namespace kiln {
namespace {

std::string Field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string Real(double x, const char* format = "%.4g") {
  if (!std::isfinite(x)) return "";
  char buf[40];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

std::string Count(long long x) { return x > 0 ? std::to_string(x) : ""; }

}  // namespace

const std::vector<std::string>& CsvColumns() {
  static const std::vector<std::string> columns = {"section",
                                                   "method",
                                                   "table",
                                                   "dims",
                                                   "size",
                                                   "texels",
                                                   "samples_or_tol",
                                                   "threads",
                                                   "seconds",
                                                   "runs",
                                                   "evals",
                                                   "bake_err_max",
                                                   "bake_err_rms",
                                                   "lookup_linear_max",
                                                   "lookup_linear_rms",
                                                   "lookup_cubic_max",
                                                   "lookup_cubic_rms",
                                                   "lookup_linear_max_off_corner",
                                                   "bytes",
                                                   "ns_per_call",
                                                   "note"};
  return columns;
}

std::string CsvText(const std::vector<BenchRow>& rows) {
  std::string out;
  for (size_t i = 0; i < CsvColumns().size(); ++i) out += (i ? "," : "") + CsvColumns()[i];
  out += "\n";
  for (const BenchRow& r : rows) {
    std::vector<std::string> f = {Field(r.section),
                                  Field(r.method),
                                  Field(r.table),
                                  r.dims ? std::to_string(r.dims) : "",
                                  Field(r.size),
                                  Count(r.texels),
                                  Real(r.setting, "%.6g"),
                                  r.threads ? std::to_string(r.threads) : "",
                                  Real(r.seconds, "%.4g"),
                                  r.runs ? std::to_string(r.runs) : "",
                                  Count(r.evals),
                                  Real(r.bakeMax, "%.3e"),
                                  Real(r.bakeRms, "%.3e"),
                                  Real(r.linearMax, "%.3e"),
                                  Real(r.linearRms, "%.3e"),
                                  Real(r.cubicMax, "%.3e"),
                                  Real(r.cubicRms, "%.3e"),
                                  Real(r.linearMaxOffCorner, "%.3e"),
                                  Count(r.bytes),
                                  Real(r.nsPerCall, "%.4g"),
                                  Field(r.note)};
    for (size_t i = 0; i < f.size(); ++i) out += (i ? "," : "") + f[i];
    out += "\n";
  }
  return out;
}

}  // namespace kiln

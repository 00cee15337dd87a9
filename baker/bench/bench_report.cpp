// What a bench run concludes: the plot (bench.svg) and the summary lines, both from the rows.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "baker/bench/bench.h"
#include "baker/bench/svg_plot.h"

namespace kiln {
namespace {

struct Style {
  const char* name;
  const char* colour;
  Marker marker;
};

Style MethodStyle(const std::string& method) {
  if (method == "kiln")
    return {"kiln, adaptive Gauss-Kronrod (label: tol)", "#d62728", Marker::Circle};
  if (method == "kiln-fixed-rule")
    return {"kiln, fixed rule (label: declared error)", "#d62728", Marker::Diamond};
  if (method == "mc-hammersley")
    return {"Monte Carlo, Hammersley + imp. sampling (samples)", "#1f77b4", Marker::Square};
  return {"Gauss-Legendre n x n, same map (points)", "#2ca02c", Marker::Triangle};
}

std::string Short(double x) {
  char buf[32];
  if (x >= 1 && x == static_cast<long long>(x))
    std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(x));
  else
    std::snprintf(buf, sizeof buf, "%.0e", x);
  return buf;
}

std::string Fmt(const char* format, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, a);
  return buf;
}

/// Table names in first-seen order.
std::vector<std::string> Tables(const std::vector<BenchRow>& rows, const std::string& section) {
  std::vector<std::string> out;
  for (const BenchRow& r : rows)
    if (r.section == section && std::find(out.begin(), out.end(), r.table) == out.end())
      out.push_back(r.table);
  return out;
}

const BenchRow* Find(const std::vector<BenchRow>& rows, const std::string& section,
                     const std::string& table, const std::string& method, double setting) {
  for (const BenchRow& r : rows)
    if (r.section == section && r.table == table && r.method == method &&
        (std::isnan(setting) || r.setting == setting))
      return &r;
  return nullptr;
}

std::string Errors(const BenchRow& r) {
  return "max " + Fmt("%.1e", r.bakeMax) + " (rms " + Fmt("%.1e", r.bakeRms) + ") in " +
         Fmt("%.3g", r.seconds) + " s";
}

}  // namespace

std::string BenchSvg(const std::vector<BenchRow>& rows) {
  std::vector<PlotPanel> panels;
  std::vector<std::string> sweep = Tables(rows, "sweep"), sizes = Tables(rows, "size");
  for (const std::string& table : sweep) {
    PlotPanel p;
    std::string size;
    for (const char* method : {"kiln", "kiln-fixed-rule", "mc-hammersley", "gauss-legendre"}) {
      Style st = MethodStyle(method);
      PlotSeries s{st.name, st.colour, st.marker, false, {}};
      for (const BenchRow& r : rows)
        if (r.section == "sweep" && r.table == table && r.method == method) {
          s.points.push_back({r.seconds, r.bakeMax, Short(r.setting)});
          size = r.size;
        }
      if (!s.points.empty()) p.series.push_back(s);
    }
    p.title = table + " " + size;
    p.xLabel = "bake wall time [s] (2 threads)";
    p.yLabel = "max bake error";
    p.paretoFront = true;
    panels.push_back(p);
  }
  for (const std::string& table : sizes) {
    PlotPanel p;
    p.title = table + ": lookup error vs size";
    p.xLabel = "table bytes (float32); label: nodes per axis";
    p.yLabel = "lookup error (max solid, rms dashed)";
    PlotSeries kl{"kiln tol 1e-8, linear filter, max", "#d62728", Marker::Circle, false, {}};
    PlotSeries ko{
        "kiln tol 1e-8, linear filter, max off the corner", "#9467bd", Marker::Triangle, false, {}};
    PlotSeries klr{"kiln tol 1e-8, linear filter, rms", "#d62728", Marker::Circle, true, {}};
    PlotSeries kcr{"kiln tol 1e-8, cubic filter, rms", "#ff7f0e", Marker::Diamond, true, {}};
    PlotSeries mlr{"Monte Carlo, linear filter, rms", "#1f77b4", Marker::Square, true, {}};
    for (const BenchRow& r : rows) {
      if (r.section != "size" || r.table != table) continue;
      std::string label = r.size.substr(0, r.size.find('x'));
      double bytes = static_cast<double>(r.bytes);
      if (r.method == "kiln") {
        kl.points.push_back({bytes, r.linearMax, label});
        ko.points.push_back({bytes, r.linearMaxOffCorner, ""});
        klr.points.push_back({bytes, r.linearRms, ""});
        kcr.points.push_back({bytes, r.cubicRms, ""});
      } else {
        mlr.name = "Monte Carlo " + Short(r.setting) + " samples, linear filter, rms";
        mlr.points.push_back({bytes, r.linearRms, ""});
      }
    }
    p.series = {kl, ko, klr, kcr, mlr};
    panels.push_back(p);
  }
  int columns = static_cast<int>(std::max(sweep.size(), sizes.size()));
  return SvgPlot(
      "kiln bench: bake error against time (top), lookup error against table size (bottom)", panels,
      columns);
}

namespace {

/// How kiln's adaptive or fixed rule `k` was set: "tol 1e-06", or "the fixed rule".
std::string HowSet(const BenchRow& k) {
  return k.method == "kiln-fixed-rule" ? std::string("the fixed rule") : "tol " + Short(k.setting);
}

/// The summary line of one table of the "sweep" section: kiln against Monte Carlo and
/// Gauss-Legendre at equal error and at their best; "" when the table has no kiln row.
std::string SweepLine(const std::vector<BenchRow>& rows, const std::string& table) {
  const BenchRow* mc = Find(rows, "sweep", table, "mc-hammersley", 1024);
  std::vector<const BenchRow*> kiln, mcs, gls;
  for (const BenchRow& r : rows)
    if (r.section == "sweep" && r.table == table) {
      if (r.method == "kiln" || r.method == "kiln-fixed-rule") kiln.push_back(&r);
      if (r.method == "mc-hammersley") mcs.push_back(&r);
      if (r.method == "gauss-legendre") gls.push_back(&r);
    }
  if (kiln.empty()) return "";
  auto byTime = [](const BenchRow* a, const BenchRow* b) { return a->seconds < b->seconds; };
  auto byError = [](const BenchRow* a, const BenchRow* b) { return a->bakeMax < b->bakeMax; };
  std::sort(kiln.begin(), kiln.end(), byTime);
  const BenchRow* best = *std::min_element(kiln.begin(), kiln.end(), byError);
  std::string line = table + " " + kiln.front()->size + ":";
  if (mc) {
    line += " 1024-sample MC " + Errors(*mc) + ";";
    const BenchRow* match = nullptr;
    for (const BenchRow* k : kiln)
      if (k->bakeMax <= mc->bakeMax) {
        match = k;
        break;
      }
    if (match) {
      line += " kiln reaches that error (or less) fastest with " + HowSet(*match) + ": " +
              Errors(*match) + " = " + Fmt("%.3g", match->seconds / mc->seconds) + "x the MC time;";
      // Equal error: where the MC rows' error-time line (least squares in log-log over the
      // rows with >= 1024 samples) reaches that kiln row's max error. An extrapolation.
      double sx = 0, sy = 0, sxx = 0, sxy = 0;
      int n = 0;
      for (const BenchRow& r : rows)
        if (r.section == "sweep" && r.table == table && r.method == "mc-hammersley" &&
            r.setting >= 1024 && r.seconds > 0 && r.bakeMax > 0) {
          double x = std::log10(r.seconds), y = std::log10(r.bakeMax);
          sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
        }
      double slope = n >= 2 ? (n * sxy - sx * sy) / (n * sxx - sx * sx) : 0;
      if (slope < 0) {
        double a = (sy - slope * sx) / n;
        double need = std::pow(10.0, (std::log10(match->bakeMax) - a) / slope);
        line += " MC's max error falls as time^" + Fmt("%.2f", slope) + " (fit over " +
                std::to_string(n) + " rows), so it would need about " + Fmt("%.2g", need) +
                " s for kiln's " + Fmt("%.1e", match->bakeMax) + " (extrapolated): kiln is ~" +
                Fmt("%.2g", need / match->seconds) + "x faster at equal error;";
      }
    }
  }
  line += " kiln's best: " + HowSet(*best) + ", " + Errors(*best) + ";";
  if (!mcs.empty()) {
    const BenchRow* m = *std::min_element(mcs.begin(), mcs.end(), byError);
    line += " best MC (" + Short(m->setting) + " samples) " + Errors(*m) + ";";
    // Measured, no extrapolation: the fastest kiln row at least as accurate as MC's best.
    for (const BenchRow* k : kiln)
      if (k->bakeMax <= m->bakeMax) {
        line += " kiln beats that with " + HowSet(*k) + " in " + Fmt("%.3g", k->seconds) + " s (" +
                Fmt("%.2g", k->seconds / m->seconds) + "x the time, " +
                Fmt("%.2g", m->bakeMax / k->bakeMax) + "x smaller max error);";
        break;
      }
  }
  if (!gls.empty()) {
    const BenchRow* g = *std::min_element(gls.begin(), gls.end(), byError);
    line += " best Gauss-Legendre (" + Short(g->setting) + " points) " + Errors(*g) + ".";
  }
  return line;
}

/// The summary line of one table of the "size" section: its lookup errors at each size.
std::string SizeLine(const std::vector<BenchRow>& rows, const std::string& table) {
  std::string line = table +
                     " lookup error against size (kiln tol 1e-8; linear max / linear max off "
                     "the corner / linear rms / cubic rms):";
  for (const BenchRow& r : rows)
    if (r.section == "size" && r.table == table && r.method == "kiln")
      line += " " + r.size + " (" + std::to_string(r.bytes) + " B): " + Fmt("%.1e", r.linearMax) +
              " / " + Fmt("%.1e", r.linearMaxOffCorner) + " / " + Fmt("%.1e", r.linearRms) + " / " +
              Fmt("%.1e", r.cubicRms) + ";";
  return line;
}

/// The summary line of the "baker-issue" section (ggx-dfg, kiln against the peers' Monte Carlo
/// bake as commands); "" without its rows.
std::string BakerIssueLine(const std::vector<BenchRow>& rows) {
  const double nan = NAN;
  const BenchRow* k = Find(rows, "baker-issue", "ggx-dfg", "kiln", nan);
  const BenchRow* cmd = Find(rows, "baker-issue", "ggx-dfg", "kiln-bake-command", nan);
  const BenchRow* mc = Find(rows, "baker-issue", "ggx-dfg", "mc-hammersley", nan);
  const BenchRow* written = Find(rows, "baker-issue", "ggx-dfg", "kiln-bake-written", nan);
  const BenchRow* mcWritten = Find(rows, "baker-issue", "ggx-dfg", "mc-hammersley-written", nan);
  if (k && cmd && mc) {
    std::string line =
        "baker issue, ggx-dfg " + k->size + " on 2 threads: kiln bake " +
        Fmt("%.3g", cmd->seconds) + " s as a command (texels " + Fmt("%.3g", k->seconds) +
        " s), bake error max " + Fmt("%.1e", k->bakeMax) + " rms " + Fmt("%.1e", k->bakeRms) +
        "; " + Short(mc->setting) + "-sample Hammersley MC " + Fmt("%.3g", mc->seconds) +
        " s, bake error max " + Fmt("%.1e", mc->bakeMax) + " rms " + Fmt("%.1e", mc->bakeRms) +
        "; kiln texels take " + Fmt("%.3g", k->seconds / mc->seconds) + "x the MC time for " +
        Fmt("%.3g", mc->bakeMax / k->bakeMax) + "x smaller max error; the whole command " +
        Fmt("%.3g", cmd->seconds / mc->seconds) + "x";
    if (written && mcWritten)
      line += "; both written to EXR, no lookup-error check: " + Fmt("%.3g", written->seconds) +
              " s against " + Fmt("%.3g", mcWritten->seconds) + " s, " +
              Fmt("%.3g", written->seconds / mcWritten->seconds) + "x";
    if (const BenchRow* perTexel =
            Find(rows, "baker-issue", "ggx-dfg", "mc-hammersley-per-texel", nan))
      line += "; MC with per-texel sampling (as Filament's generator) " +
              Fmt("%.3g", perTexel->seconds) + " s: the whole kiln command " +
              Fmt("%.3g", cmd->seconds / perTexel->seconds) + "x";
    return line;
  }
  return "";
}

/// The summary line of the "runtime" section: nanoseconds per call of each lookup.
std::string RuntimeLine(const std::vector<BenchRow>& rows) {
  std::string lookups = "runtime ns/call (1 thread):";
  for (const BenchRow& r : rows) {
    if (r.section != "runtime") continue;
    std::string what =
        r.method == "directional-albedo" ? r.method + " tol " + Short(r.setting) : r.method;
    lookups += " " + r.table + (r.size.empty() ? "" : " " + r.size) + " " + what + " " +
               Fmt("%.3g", r.nsPerCall) + ";";
  }
  return lookups;
}

}  // namespace

std::vector<std::string> BenchSummary(const std::vector<BenchRow>& rows) {
  std::vector<std::string> out;
  for (const std::string& table : Tables(rows, "sweep"))
    if (std::string line = SweepLine(rows, table); !line.empty()) out.push_back(line);
  for (const std::string& table : Tables(rows, "size")) out.push_back(SizeLine(rows, table));
  if (std::string line = BakerIssueLine(rows); !line.empty()) out.push_back(line);
  for (const char* method : {"kiln", "mc-hammersley"}) {
    std::vector<const BenchRow*> t;
    for (const BenchRow& r : rows)
      if (r.section == "threads" && r.method == method) t.push_back(&r);
    if (t.size() == 2)
      out.push_back(std::string("threads, ") + method + " " + t[0]->table + " " + t[0]->size +
                    ": " + Fmt("%.3g", t[0]->seconds) + " s on 1 thread, " +
                    Fmt("%.3g", t[1]->seconds) + " s on " + std::to_string(t[1]->threads) + " (" +
                    Fmt("%.2f", t[0]->seconds / t[1]->seconds) + "x)" +
                    (std::string(method) == "kiln" ? "; " + t[1]->note : std::string()));
  }
  out.push_back(RuntimeLine(rows));
  return out;
}

}  // namespace kiln

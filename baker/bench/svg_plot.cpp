#include "baker/bench/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace kiln {
namespace {

constexpr double kPlotW = 330, kPlotH = 250;          // plot area of a panel
constexpr double kLeft = 64, kRight = 24, kTop = 34;  // margins around it
constexpr double kAxisBelow = 44, kLegendLine = 15;

std::string Num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", x);
  return buf;
}

std::string Decade(int e) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "1e%d", e);
  return buf;
}

bool Usable(const PlotPoint& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && p.x > 0 && p.y > 0;
}

/// Decade-aligned log range [lo, hi] (exponents) covering every usable value.
void LogRange(const std::vector<double>& v, int& lo, int& hi) {
  if (v.empty()) {
    lo = 0;
    hi = 1;
    return;
  }
  auto [mn, mx] = std::minmax_element(v.begin(), v.end());
  lo = static_cast<int>(std::floor(std::log10(*mn) + 1e-9));
  hi = static_cast<int>(std::ceil(std::log10(*mx) - 1e-9));
  if (hi <= lo) hi = lo + 1;
}

std::string MarkerSvg(Marker m, double x, double y, const std::string& colour) {
  std::string fill = "fill=\"" + colour + "\"";
  switch (m) {
    case Marker::Circle:
      return "<circle cx=\"" + Num(x) + "\" cy=\"" + Num(y) + "\" r=\"3.5\" " + fill + "/>";
    case Marker::Square:
      return "<rect x=\"" + Num(x - 3.5) + "\" y=\"" + Num(y - 3.5) +
             "\" width=\"7\" height=\"7\" " + fill + "/>";
    case Marker::Triangle:
      return "<polygon points=\"" + Num(x) + "," + Num(y - 4.5) + " " + Num(x - 4) + "," +
             Num(y + 3) + " " + Num(x + 4) + "," + Num(y + 3) + "\" " + fill + "/>";
    case Marker::Diamond:
      return "<polygon points=\"" + Num(x) + "," + Num(y - 4.5) + " " + Num(x - 4) + "," + Num(y) +
             " " + Num(x) + "," + Num(y + 4.5) + " " + Num(x + 4) + "," + Num(y) + "\" " + fill +
             "/>";
  }
  return "";
}

std::string Text(double x, double y, const std::string& s, const std::string& attrs) {
  return "<text x=\"" + Num(x) + "\" y=\"" + Num(y) + "\" " + attrs + ">" + XmlEscape(s) +
         "</text>";
}

/// One panel at offset (ox, oy); returns its SVG group.
std::string Panel(const PlotPanel& p, double ox, double oy) {
  std::vector<double> xs, ys;
  for (const PlotSeries& s : p.series)
    for (const PlotPoint& q : s.points)
      if (Usable(q)) {
        xs.push_back(q.x);
        ys.push_back(q.y);
      }
  int x0, x1, y0, y1;
  LogRange(xs, x0, x1);
  LogRange(ys, y0, y1);
  double px = ox + kLeft, py = oy + kTop;
  auto X = [&](double x) { return px + (std::log10(x) - x0) / (x1 - x0) * kPlotW; };
  auto Y = [&](double y) { return py + kPlotH - (std::log10(y) - y0) / (y1 - y0) * kPlotH; };
  std::string out = "<g>\n";
  out += Text(px + kPlotW / 2, oy + 20, p.title,
              "text-anchor=\"middle\" font-size=\"14\" font-weight=\"bold\"") +
         "\n";
  out += "<rect x=\"" + Num(px) + "\" y=\"" + Num(py) + "\" width=\"" + Num(kPlotW) +
         "\" height=\"" + Num(kPlotH) + "\" fill=\"none\" stroke=\"#444\"/>\n";
  // Decade grid and labels; minor ticks at 2..9 when there are few decades.
  for (int e = x0; e <= x1; ++e) {
    double x = px + static_cast<double>(e - x0) / (x1 - x0) * kPlotW;
    out += "<line x1=\"" + Num(x) + "\" y1=\"" + Num(py) + "\" x2=\"" + Num(x) + "\" y2=\"" +
           Num(py + kPlotH) + "\" stroke=\"#ddd\"/>\n";
    out += Text(x, py + kPlotH + 15, Decade(e), "text-anchor=\"middle\" font-size=\"10\"") + "\n";
    for (int m = 2; e < x1 && x1 - x0 <= 6 && m <= 9; ++m) {
      double xm = X(m * std::pow(10.0, e));
      out += "<line x1=\"" + Num(xm) + "\" y1=\"" + Num(py + kPlotH) + "\" x2=\"" + Num(xm) +
             "\" y2=\"" + Num(py + kPlotH - 4) + "\" stroke=\"#444\"/>\n";
    }
  }
  for (int e = y0; e <= y1; ++e) {
    double y = py + kPlotH - static_cast<double>(e - y0) / (y1 - y0) * kPlotH;
    out += "<line x1=\"" + Num(px) + "\" y1=\"" + Num(y) + "\" x2=\"" + Num(px + kPlotW) +
           "\" y2=\"" + Num(y) + "\" stroke=\"#ddd\"/>\n";
    out += Text(px - 5, y + 3.5, Decade(e), "text-anchor=\"end\" font-size=\"10\"") + "\n";
  }
  out +=
      Text(px + kPlotW / 2, py + kPlotH + 32, p.xLabel, "text-anchor=\"middle\" font-size=\"11\"") +
      "\n";
  out += "<text transform=\"translate(" + Num(ox + 16) + "," + Num(py + kPlotH / 2) +
         ") rotate(-90)\" text-anchor=\"middle\" font-size=\"11\">" + XmlEscape(p.yLabel) +
         "</text>\n";
  // Series: a polyline through the usable points, markers, labels.
  for (const PlotSeries& s : p.series) {
    std::string pts;
    for (const PlotPoint& q : s.points)
      if (Usable(q)) pts += Num(X(q.x)) + "," + Num(Y(q.y)) + " ";
    if (!pts.empty())
      out += "<polyline points=\"" + pts + "\" fill=\"none\" stroke=\"" + s.colour +
             "\" stroke-width=\"1.5\"" + (s.dashed ? " stroke-dasharray=\"5,3\"" : "") + "/>\n";
    for (const PlotPoint& q : s.points) {
      if (!Usable(q)) continue;
      out += MarkerSvg(s.marker, X(q.x), Y(q.y), s.colour) + "\n";
      if (!q.label.empty())
        out += Text(X(q.x) + 5, Y(q.y) - 5, q.label, "font-size=\"8\" fill=\"" + s.colour + "\"") +
               "\n";
    }
  }
  // Pareto front over every series of the panel: sorted by x, keep strictly decreasing y.
  if (p.paretoFront) {
    std::vector<PlotPoint> all;
    for (const PlotSeries& s : p.series)
      for (const PlotPoint& q : s.points)
        if (Usable(q)) all.push_back(q);
    std::sort(all.begin(), all.end(), [](const PlotPoint& a, const PlotPoint& b) {
      return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    std::vector<PlotPoint> front;
    for (const PlotPoint& q : all)
      if (front.empty() || q.y < front.back().y) front.push_back(q);
    if (!front.empty()) {
      std::string d = "M" + Num(X(front[0].x)) + "," + Num(Y(front[0].y));
      for (size_t i = 1; i < front.size(); ++i)
        d += " H" + Num(X(front[i].x)) + " V" + Num(Y(front[i].y));
      out += "<path d=\"" + d +
             "\" fill=\"none\" stroke=\"#000\" stroke-width=\"1\" "
             "stroke-dasharray=\"2,2\"/>\n";
      for (const PlotPoint& q : front)
        out += "<circle cx=\"" + Num(X(q.x)) + "\" cy=\"" + Num(Y(q.y)) +
               "\" r=\"7\" fill=\"none\" stroke=\"#000\"/>\n";
    }
  }
  // Legend under the axis label.
  double ly = py + kPlotH + kAxisBelow + 4;
  for (const PlotSeries& s : p.series) {
    out += "<line x1=\"" + Num(px) + "\" y1=\"" + Num(ly) + "\" x2=\"" + Num(px + 22) + "\" y2=\"" +
           Num(ly) + "\" stroke=\"" + s.colour + "\" stroke-width=\"1.5\"" +
           (s.dashed ? " stroke-dasharray=\"5,3\"" : "") + "/>\n";
    out += MarkerSvg(s.marker, px + 11, ly, s.colour) + "\n";
    out += Text(px + 28, ly + 3.5, s.name, "font-size=\"10\"") + "\n";
    ly += kLegendLine;
  }
  if (p.paretoFront) {
    out += "<circle cx=\"" + Num(px + 11) + "\" cy=\"" + Num(ly) +
           "\" r=\"6\" fill=\"none\" stroke=\"#000\"/>\n";
    out += Text(px + 28, ly + 3.5, "Pareto front (nothing both faster and more accurate)",
                "font-size=\"10\"") +
           "\n";
  }
  out += "</g>\n";
  return out;
}

}  // namespace

std::string XmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string SvgPlot(const std::string& title, const std::vector<PlotPanel>& panels, int columns) {
  columns = std::max(1, std::min<int>(columns, std::max<size_t>(panels.size(), 1)));
  size_t maxSeries = 0;
  for (const PlotPanel& p : panels)
    maxSeries = std::max(maxSeries, p.series.size() + (p.paretoFront ? 1 : 0));
  double panelW = kLeft + kPlotW + kRight;
  double panelH = kTop + kPlotH + kAxisBelow + kLegendLine * maxSeries + 10;
  int rows = static_cast<int>((panels.size() + columns - 1) / columns);
  double width = panelW * columns, height = 36 + panelH * std::max(rows, 1);
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + Num(width) +
         "\" height=\"" + Num(height) + "\" viewBox=\"0 0 " + Num(width) + " " + Num(height) +
         "\" font-family=\"sans-serif\">\n";
  out += "<rect x=\"0\" y=\"0\" width=\"" + Num(width) + "\" height=\"" + Num(height) +
         "\" fill=\"#fff\"/>\n";
  out +=
      Text(width / 2, 24, title, "text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\"") +
      "\n";
  for (size_t i = 0; i < panels.size(); ++i) {
    double ox = panelW * static_cast<double>(i % columns);
    double oy = 36 + panelH * static_cast<double>(i / columns);
    out += Panel(panels[i], ox, oy);
  }
  out += "</svg>\n";
  return out;
}

}  // namespace kiln

// A small log-log plot writer: panels of point series as standalone SVG 1.1 (no dependency).
// Each panel has its own decade-aligned axes; non-positive or non-finite values are dropped.
// The Pareto front of a panel (points no other point beats in both x and y, smaller being
// better) is drawn as a dashed staircase with its points ringed.
#pragma once
#include <string>
#include <vector>

namespace kiln {

struct PlotPoint {
  double x = 0, y = 0;
  std::string label;  ///< short text next to the marker ("1e-6", "1024"), may be empty
};

enum class Marker { Circle, Square, Triangle, Diamond };

struct PlotSeries {
  std::string name;    ///< legend text
  std::string colour;  ///< SVG colour, e.g. "#d62728"
  Marker marker = Marker::Circle;
  bool dashed = false;
  std::vector<PlotPoint> points;  ///< joined in this order
};

struct PlotPanel {
  std::string title, xLabel, yLabel;
  std::vector<PlotSeries> series;
  bool paretoFront = false;
};

/// The SVG text of `panels` laid out in `columns` columns under `title`.
std::string SvgPlot(const std::string& title, const std::vector<PlotPanel>& panels, int columns);

/// Escapes &, <, >, " for SVG text and attributes.
std::string XmlEscape(const std::string& text);

}  // namespace kiln

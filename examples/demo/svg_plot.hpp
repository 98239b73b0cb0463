#pragma once
// A minimal SVG line chart (log-scale y), enough for the sweep figures without a plotting
// dependency in the C++ build: title, labelled axes, ticks, legend. Values above `y_cap` (an
// unstable identified model's error, say) are drawn at the top edge as open circles and noted.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace bonl_demo {

struct Series {
  std::string label;
  std::string color;
  std::vector<double> y;
};

struct Chart {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<double> x;
  std::vector<Series> series;
  double y_cap = 1e300;  ///< values above are off scale
};

/// Writes `charts` into one SVG file, `columns` panels per row.
inline void write_svg(const std::string& path, const std::vector<Chart>& charts, std::size_t columns = 2) {
  const double panel_w = 560, panel_h = 470, left = 80, right = 20, top = 40, bottom = 150;
  const std::size_t rows = (charts.size() + columns - 1) / columns;
  std::ostringstream svg;
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << panel_w * columns << "' height='" << panel_h * rows
      << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n";
  for (std::size_t c = 0; c < charts.size(); ++c) {
    const Chart& chart = charts[c];
    const double ox = static_cast<double>(c % columns) * panel_w;
    const double oy = static_cast<double>(c / columns) * panel_h;
    double y_min = 1e300, y_max = -1e300;
    bool off_scale = false;
    for (const Series& s : chart.series) {
      for (double v : s.y) {
        if (std::isfinite(v) && v > 0 && v <= chart.y_cap) {
          y_min = std::min(y_min, v);
          y_max = std::max(y_max, v);
        } else {
          off_scale = true;
        }
      }
    }
    const double lo = std::floor(std::log10(y_min)), hi = std::ceil(std::log10(y_max)) + (y_max == y_min ? 1 : 0);
    const double x_min = chart.x.front(), x_max = chart.x.back();
    const double w = panel_w - left - right, h = panel_h - top - bottom;
    const auto px = [&](double x) { return ox + left + (x - x_min) / (x_max - x_min) * w; };
    const auto py = [&](double y) {
      return oy + top + (hi - std::log10(std::min(y, std::pow(10.0, hi)))) / (hi - lo) * h;
    };
    svg << "<text x='" << ox + panel_w / 2 << "' y='" << oy + 22
        << "' text-anchor='middle' font-size='14' font-weight='bold'>" << chart.title << "</text>\n";
    svg << "<rect x='" << ox + left << "' y='" << oy + top << "' width='" << w << "' height='" << h
        << "' fill='none' stroke='black'/>\n";
    for (double e = lo; e <= hi; e += 1) {
      svg << "<line x1='" << ox + left << "' x2='" << ox + left + w << "' y1='" << py(std::pow(10, e)) << "' y2='"
          << py(std::pow(10, e)) << "' stroke='#ddd'/>\n<text x='" << ox + left - 6 << "' y='"
          << py(std::pow(10, e)) + 4 << "' text-anchor='end'>1e" << e << "</text>\n";
    }
    for (double x : chart.x) {
      char label[32];
      std::snprintf(label, sizeof label, "%g", x);
      svg << "<line x1='" << px(x) << "' x2='" << px(x) << "' y1='" << oy + top + h << "' y2='" << oy + top + h + 5
          << "' stroke='black'/>\n<text x='" << px(x) << "' y='" << oy + top + h + 18 << "' text-anchor='middle'>"
          << label << "</text>\n";
    }
    svg << "<text x='" << ox + left + w / 2 << "' y='" << oy + top + h + 38 << "' text-anchor='middle'>"
        << chart.x_label << "</text>\n<text transform='translate(" << ox + 18 << "," << oy + top + h / 2
        << ") rotate(-90)' text-anchor='middle'>" << chart.y_label << "</text>\n";
    if (off_scale) {
      svg << "<text x='" << ox + left + w << "' y='" << oy + top - 6
          << "' text-anchor='end' font-size='11'>open circles on the top edge: off scale (unstable model)</text>\n";
    }
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
      const Series& series = chart.series[s];
      svg << "<polyline fill='none' stroke-width='2' stroke='" << series.color << "' points='";
      for (std::size_t i = 0; i < chart.x.size(); ++i) {
        const double v = std::isfinite(series.y[i]) ? series.y[i] : 1e300;
        if (v > 0) svg << px(chart.x[i]) << "," << py(v) << " ";
      }
      svg << "'/>\n";
      for (std::size_t i = 0; i < chart.x.size(); ++i) {
        if (!(std::isfinite(series.y[i]) && series.y[i] <= chart.y_cap)) {
          svg << "<circle cx='" << px(chart.x[i]) << "' cy='" << py(1e300) << "' r='5' fill='white' stroke='"
              << series.color << "' stroke-width='2'/>\n";
        }
      }
      const double ly = oy + top + h + 60 + 16 * static_cast<double>(s);
      svg << "<line x1='" << ox + left << "' x2='" << ox + left + 24 << "' y1='" << ly << "' y2='" << ly
          << "' stroke-width='2' stroke='" << series.color << "'/>\n<text x='" << ox + left + 30 << "' y='" << ly + 4
          << "'>" << series.label << "</text>\n";
    }
  }
  svg << "</svg>\n";
  std::ofstream(path) << svg.str();
}

}  // namespace bonl_demo

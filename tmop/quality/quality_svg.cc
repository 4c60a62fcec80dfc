#include "tmop/quality/quality_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "tmop/quality/svg_canvas.h"

namespace tmop {
namespace {

const char* const kInvertedColour = "#ff00ff";
const char* const kBeforeColour = "#d95f02";
const char* const kAfterColour = "#1b9e77";
constexpr int kMaxScatterPoints = 20000;

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

// A perceptually ordered ramp (dark blue -> teal -> green -> yellow), linear between 5 anchors.
std::string ramp(double t) {
  static const double anchors[5][3] = {{0.267, 0.005, 0.329},
                                       {0.231, 0.322, 0.545},
                                       {0.129, 0.569, 0.549},
                                       {0.369, 0.788, 0.384},
                                       {0.992, 0.906, 0.145}};
  t = std::clamp(std::isnan(t) ? 0.0 : t, 0.0, 1.0) * 4;
  const int i = std::min(3, static_cast<int>(t));
  const double f = t - i;
  return svg_rgb(anchors[i][0] + f * (anchors[i + 1][0] - anchors[i][0]),
                 anchors[i][1] + f * (anchors[i + 1][1] - anchors[i][1]),
                 anchors[i][2] + f * (anchors[i + 1][2] - anchors[i][2]));
}

struct Series {
  const QualityMeasure* measure;
  std::string colour;
  std::string label;
};

void legend(SvgCanvas& c, double x, double y, const std::vector<Series>& series) {
  for (std::size_t i = 0; i < series.size(); ++i) {
    const double yy = y + 16 * i;
    c.rect(x - 130, yy - 9, 10, 10, series[i].colour);
    c.text(x - 116, yy, series[i].label, 11);
  }
}

// Bars: fraction of each series' elements per bin, series side by side; the under/overflow bins
// appear when some series has values there.
void histogram_panel(SvgCanvas& c, double x, double y, double w, double h, const std::string& title,
                     const std::vector<Series>& series) {
  const Histogram& ref = series.front().measure->histogram;
  bool below = false, above = false;
  for (const Series& s : series) {
    below = below || s.measure->histogram.below > 0;
    above = above || s.measure->histogram.above > 0;
  }
  const int bins = static_cast<int>(ref.counts.size()) + below + above;
  std::vector<std::vector<double>> fractions;
  double top = 0;
  for (const Series& s : series) {
    const Histogram& hist = s.measure->histogram;
    std::vector<double> counts;
    if (below) counts.push_back(static_cast<double>(hist.below));
    for (std::int64_t n : hist.counts) counts.push_back(static_cast<double>(n));
    if (above) counts.push_back(static_cast<double>(hist.above));
    double total = 0;
    for (double n : counts) total += n;
    for (double& n : counts) n = total > 0 ? n / total : 0;
    for (double n : counts) top = std::max(top, n);
    fractions.push_back(counts);
  }
  if (top <= 0) top = 1;
  const double left = x + 50, right = x + w - 10, base = y + h - 40, ceiling = y + 30;
  c.text(x + w / 2, y + 16, title, 13, "middle");
  c.line(left, base, right, base, "#000000");
  c.line(left, base, left, ceiling, "#000000");
  c.text(left - 4, base + 4, "0%", 10, "end");
  c.text(left - 4, ceiling + 4, fmt("%.0f%%", 100 * top), 10, "end");
  c.text(x + 12, (base + ceiling) / 2, "elements", 10, "middle", -90);
  const double group = (right - left) / bins;
  const double bar = 0.8 * group / series.size();
  for (std::size_t s = 0; s < series.size(); ++s) {
    for (int b = 0; b < bins; ++b) {
      const double height = (base - ceiling) * fractions[s][b] / top;
      c.rect(left + b * group + 0.1 * group + s * bar, base - height, bar, height,
             series[s].colour);
    }
  }
  // Labels at the bin edges (thinned to about 10), and the overflow bins by name.
  const int edges = static_cast<int>(ref.edges.size());
  const int step = std::max(1, (edges + 9) / 10);
  for (int e = 0; e < edges; e += step)
    c.text(left + (e + below) * group, base + 14, fmt("%g", ref.edges[e]), 10, "middle");
  if (below) c.text(left + 0.5 * group, base + 28, "<" + fmt("%g", ref.edges.front()), 9, "middle");
  if (above) c.text(right - 0.5 * group, base + 28, ">" + fmt("%g", ref.edges.back()), 9, "middle");
  if (series.size() > 1 || !series.front().label.empty()) legend(c, right, ceiling, series);
}

struct Scatter {
  const QualityMeasure* x;
  const QualityMeasure* y;
  std::string colour;
  std::string label;
};

void scatter_panel(SvgCanvas& c, double x, double y, double w, double h, const std::string& title,
                   const std::string& x_label, const std::string& y_label, double x_max,
                   double y_max, bool sliver_corner, const std::vector<Scatter>& series) {
  const double left = x + 50, right = x + w - 10, base = y + h - 40, ceiling = y + 30;
  auto px = [&](double v) { return left + (right - left) * std::clamp(v / x_max, 0.0, 1.0); };
  auto py = [&](double v) { return base - (base - ceiling) * std::clamp(v / y_max, 0.0, 1.0); };
  c.text(x + w / 2, y + 16, title, 13, "middle");
  if (sliver_corner) {
    c.rect(px(0), py(y_max), px(10) - px(0), py(150) - py(y_max), "#cccccc");
    c.text(px(10) + 4, py(160), "slivers", 10);
  }
  c.line(left, base, right, base, "#000000");
  c.line(left, base, left, ceiling, "#000000");
  for (double v = 0; v <= x_max + 1e-9; v += x_max / 6)
    c.text(px(v), base + 14, fmt("%g", v), 10, "middle");
  for (double v = 0; v <= y_max + 1e-9; v += y_max / 6)
    c.text(left - 4, py(v) + 4, fmt("%g", v), 10, "end");
  c.text((left + right) / 2, base + 30, x_label, 11, "middle");
  c.text(x + 12, (base + ceiling) / 2, y_label, 11, "middle", -90);
  for (const Scatter& s : series) {
    std::int64_t valid = 0;
    for (double v : s.x->values) valid += std::isfinite(v);
    const std::int64_t stride =
        std::max<std::int64_t>(1, (valid + kMaxScatterPoints - 1) / kMaxScatterPoints);
    std::int64_t seen = 0;
    for (std::size_t i = 0; i < s.x->values.size(); ++i) {
      const double vx = s.x->values[i], vy = s.y->values[i];
      if (!std::isfinite(vx) || !std::isfinite(vy)) continue;
      if (seen++ % stride == 0) c.circle(px(vx), py(vy), 1.6, s.colour, 0.5);
    }
  }
  std::vector<Series> keys;
  for (const Scatter& s : series) keys.push_back({nullptr, s.colour, s.label});
  if (series.size() > 1 || !series.front().label.empty()) legend(c, right, ceiling, keys);
}

bool applies(const QualityMeasure& m) { return m.count + m.infinite > 0; }

// The histogram and scatter panels of one or two reports.
std::string panels(const std::vector<const QualityReport*>& reports,
                   const std::vector<std::string>& labels) {
  const std::vector<std::string> colours =
      reports.size() == 1 ? std::vector<std::string>{"#4477aa"}
                          : std::vector<std::string>{kBeforeColour, kAfterColour};
  const QualityReport& first = *reports.front();
  auto any = [&](const QualityMeasure QualityReport::*m) {
    for (const QualityReport* r : reports)
      if (applies(r->*m)) return true;
    return false;
  };
  auto series_of = [&](const QualityMeasure QualityReport::*m) {
    std::vector<Series> s;
    for (std::size_t i = 0; i < reports.size(); ++i)
      s.push_back({&(reports[i]->*m), colours[i], labels[i]});
    return s;
  };
  const bool dihedral = any(&QualityReport::min_dihedral);
  const QualityMeasure QualityReport::*lo =
      dihedral ? &QualityReport::min_dihedral : &QualityReport::min_angle;
  const QualityMeasure QualityReport::*hi =
      dihedral ? &QualityReport::max_dihedral : &QualityReport::max_angle;
  const std::string angle = dihedral ? "dihedral angle" : "angle";

  struct Panel {
    std::string title;
    std::vector<Series> series;
  };
  std::vector<Panel> hists;
  if (any(&QualityReport::mean_ratio))
    hists.push_back({"mean ratio", series_of(&QualityReport::mean_ratio)});
  if (any(&QualityReport::scaled_jacobian))
    hists.push_back({"scaled Jacobian", series_of(&QualityReport::scaled_jacobian)});
  const bool angles = any(lo);
  if (angles && reports.size() == 1) {
    hists.push_back(
        {angle + "s (deg)",
         {{&(first.*lo), "#4477aa", "min " + angle}, {&(first.*hi), "#cc6677", "max " + angle}}});
  } else if (angles) {
    hists.push_back({"min " + angle + " (deg)", series_of(lo)});
    hists.push_back({"max " + angle + " (deg)", series_of(hi)});
  }
  const double pw = 440, ph = 320;
  const int count = static_cast<int>(hists.size()) + (angles ? 1 : 0);
  const int rows = std::max(1, (count + 1) / 2);
  SvgCanvas c(2 * pw, rows * ph + 30);
  std::string heading = "tmop quality";
  for (std::size_t i = 0; i < reports.size(); ++i) {
    heading += (i ? ", " : ": ") + (labels[i].empty() ? std::string() : labels[i] + " ") +
               fmt("%.0f elements", static_cast<double>(reports[i]->num_elements)) +
               fmt(", %.0f inverted", static_cast<double>(reports[i]->inverted_cells));
  }
  c.text(pw, 20, heading, 14, "middle");
  int k = 0;
  for (const Panel& p : hists) {
    histogram_panel(c, (k % 2) * pw, 30 + (k / 2) * ph, pw, ph, p.title, p.series);
    ++k;
  }
  if (angles) {
    std::vector<Scatter> s;
    for (std::size_t i = 0; i < reports.size(); ++i)
      s.push_back({&(reports[i]->*lo), &(reports[i]->*hi), colours[i], labels[i]});
    scatter_panel(c, (k % 2) * pw, 30 + (k / 2) * ph, pw, ph,
                  "max vs min " + angle + " per element", "min " + angle + " (deg)",
                  "max " + angle + " (deg)", 90, 180, dihedral, s);
  }
  return c.finish();
}

// A 2D mesh filled by per-cell quality, with a colour bar: planar meshes in their plane, surface
// meshes in an orthographic view from direction (1, -1.3, 0.9) with cells painted back to front
// (a closed surface hides its far side).
std::string planar_map(const Mesh& mesh, const QualityReport& r) {
  const bool surface = mesh.space_dim == 3 && !r.planar;
  double right[3] = {1, 0, 0}, up[3] = {0, 1, 0}, toward[3] = {0, 0, 1};
  if (surface) {
    const double d[3] = {1, -1.3, 0.9};
    const double dn = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int k = 0; k < 3; ++k) toward[k] = d[k] / dn;
    // right = z x toward, normalised; up = toward x right.
    right[0] = -toward[1];
    right[1] = toward[0];
    right[2] = 0;
    const double rn = std::sqrt(right[0] * right[0] + right[1] * right[1]);
    right[0] /= rn;
    right[1] /= rn;
    up[0] = toward[1] * right[2] - toward[2] * right[1];
    up[1] = toward[2] * right[0] - toward[0] * right[2];
    up[2] = toward[0] * right[1] - toward[1] * right[0];
  }
  auto project = [&](const double* x, double* p) {
    const double z = mesh.space_dim == 3 ? x[2] : 0;
    p[0] = right[0] * x[0] + right[1] * x[1] + right[2] * z;
    p[1] = up[0] * x[0] + up[1] * x[1] + up[2] * z;
    return toward[0] * x[0] + toward[1] * x[1] + toward[2] * z;  // depth, larger = nearer
  };
  std::vector<double> proj(2 * mesh.num_vertices()), depth(mesh.num_vertices());
  for (int v = 0; v < mesh.num_vertices(); ++v)
    depth[v] = project(mesh.vertex(v), proj.data() + 2 * v);
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], proj[2 * v + k]);
      hi[k] = std::max(hi[k], proj[2 * v + k]);
    }
  const double size = 640, margin = 40;
  const double span = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-300});
  const double scale = size / span;
  // Centre the drawing in the square plot area.
  const double shift_x = (size - (hi[0] - lo[0]) * scale) / 2;
  const double shift_y = (size - (hi[1] - lo[1]) * scale) / 2;
  SvgCanvas c(size + 2 * margin + 120, size + 2 * margin);
  const bool thin = r.num_elements > 200000;  // no outlines: keeps huge plots readable and small
  const std::string stroke = thin ? "none" : "#333333";
  const double stroke_width = std::min(0.5, 200.0 / std::sqrt(std::max<double>(1, r.num_elements)));
  double worst = std::numeric_limits<double>::infinity();  // as worst_quality.h
  std::vector<int> order;
  for (int cell = 0; cell < mesh.num_cells(); ++cell)
    if (cell_info(mesh.cell_types[cell]).dim == 2) order.push_back(cell);
  if (surface) {
    std::vector<double> key(mesh.num_cells(), 0);
    for (int cell : order) {
      const int k = cell_info(mesh.cell_types[cell]).num_corners;
      for (int i = 0; i < k; ++i) key[cell] += depth[mesh.cell(cell)[i]] / k;
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
  }
  for (int cell : order) {
    const CellType type = mesh.cell_types[cell];
    const CellInfo& info = cell_info(type);
    if (info.dim != 2) continue;
    // 2D edges run around the polygon; quadratic cells put edge e's mid node at num_corners + e.
    double xy[16];
    int n = 0;
    const std::int32_t* nodes = mesh.cell(cell);
    auto add = [&](int local) {
      const double* x = proj.data() + 2 * nodes[local];
      xy[2 * n] = margin + shift_x + (x[0] - lo[0]) * scale;
      xy[2 * n + 1] = margin + size - shift_y - (x[1] - lo[1]) * scale;
      ++n;
    };
    for (int e = 0; e < info.num_edges; ++e) {
      add(info.edges[e][0]);
      if (info.order == 2) add(info.num_corners + e);
    }
    const double q = std::isnan(r.mean_ratio.values[cell]) ? r.scaled_jacobian.values[cell]
                                                           : r.mean_ratio.values[cell];
    worst = std::min(worst, q);
    c.polygon(xy, n, r.inverted[cell] ? kInvertedColour : ramp(q), stroke, stroke_width);
  }
  // Colour bar.
  const double bx = size + 2 * margin, top = margin, height = size * 0.6;
  for (int i = 0; i < 50; ++i)
    c.rect(bx, top + height * (49 - i) / 50, 20, height / 50 + 0.5, ramp((i + 0.5) / 50));
  for (int i = 0; i <= 4; ++i)
    c.text(bx + 26, top + height * (1 - i / 4.0) + 4, fmt("%g", i / 4.0), 11);
  const bool simplices = r.mean_ratio.count > 0 && r.scaled_jacobian.count == r.mean_ratio.count;
  c.text(bx, top - 12, simplices ? "mean ratio" : "quality", 12);
  c.rect(bx, top + height + 20, 20, 12, kInvertedColour);
  c.text(bx + 26, top + height + 30, fmt("inverted (%.0f)", static_cast<double>(r.inverted_cells)),
         11);
  c.text(margin, 24,
         fmt("tmop quality: %.0f elements", static_cast<double>(r.num_elements)) +
             fmt(", worst %.4g", worst),
         14);
  return c.finish();
}

}  // namespace

std::string quality_svg(const Mesh& mesh, const QualityReport& report) {
  if (report.dim == 2 && (report.planar || mesh.space_dim == 3)) return planar_map(mesh, report);
  return panels({&report}, {""});
}

std::string quality_svg_compare(const QualityReport& before, const QualityReport& after,
                                const std::string& before_label, const std::string& after_label) {
  return panels({&before, &after}, {before_label, after_label});
}

}  // namespace tmop

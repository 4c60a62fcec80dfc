#include "tmop/quality/svg_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tmop {
namespace {

std::string f2(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", std::isfinite(v) ? v : 0.0);
  return buf;
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
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

}  // namespace

SvgCanvas::SvgCanvas(double width, double height) : width_(width), height_(height) {}

void SvgCanvas::rect(double x, double y, double w, double h, const std::string& fill,
                     const std::string& stroke, double opacity) {
  body_ += "<rect x=\"" + f2(x) + "\" y=\"" + f2(y) + "\" width=\"" + f2(std::max(w, 0.0)) +
           "\" height=\"" + f2(std::max(h, 0.0)) + "\" fill=\"" + fill + "\" stroke=\"" + stroke +
           "\"";
  if (opacity < 1) body_ += " fill-opacity=\"" + f2(opacity) + "\"";
  body_ += "/>\n";
}

void SvgCanvas::line(double x1, double y1, double x2, double y2, const std::string& stroke,
                     double width) {
  body_ += "<line x1=\"" + f2(x1) + "\" y1=\"" + f2(y1) + "\" x2=\"" + f2(x2) + "\" y2=\"" +
           f2(y2) + "\" stroke=\"" + stroke + "\" stroke-width=\"" + f2(width) + "\"/>\n";
}

void SvgCanvas::polygon(const double* xy, int n, const std::string& fill, const std::string& stroke,
                        double stroke_width) {
  body_ += "<polygon points=\"";
  for (int i = 0; i < n; ++i) body_ += (i ? " " : "") + f2(xy[2 * i]) + "," + f2(xy[2 * i + 1]);
  body_ += "\" fill=\"" + fill + "\" stroke=\"" + stroke + "\" stroke-width=\"" + f2(stroke_width) +
           "\"/>\n";
}

void SvgCanvas::circle(double cx, double cy, double r, const std::string& fill, double opacity) {
  body_ += "<circle cx=\"" + f2(cx) + "\" cy=\"" + f2(cy) + "\" r=\"" + f2(r) + "\" fill=\"" +
           fill + "\"";
  if (opacity < 1) body_ += " fill-opacity=\"" + f2(opacity) + "\"";
  body_ += "/>\n";
}

void SvgCanvas::text(double x, double y, const std::string& s, double size,
                     const std::string& anchor, double rotate) {
  body_ += "<text x=\"" + f2(x) + "\" y=\"" + f2(y) + "\" font-size=\"" + f2(size) +
           "\" text-anchor=\"" + anchor + "\"";
  if (rotate != 0) body_ += " transform=\"rotate(" + f2(rotate) + " " + f2(x) + " " + f2(y) + ")\"";
  body_ += ">" + escape(s) + "</text>\n";
}

std::string SvgCanvas::finish() const {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
         f2(width_) + "\" height=\"" + f2(height_) + "\" viewBox=\"0 0 " + f2(width_) + " " +
         f2(height_) + "\" font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" " +
         "fill=\"white\"/>\n" + body_ + "</svg>\n";
}

std::string svg_rgb(double r, double g, double b) {
  auto c = [](double v) { return static_cast<int>(std::lround(255 * std::clamp(v, 0.0, 1.0))); };
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c(r), c(g), c(b));
  return buf;
}

}  // namespace tmop

// tmop/quality/svg_canvas.h
// SvgCanvas: a minimal SVG 1.1 writer for the quality plots (quality_svg.h): rectangles, lines,
// polygons, circles and text in user units (y down), escaped and well-formed. Coordinates are
// printed with 2 decimals, enough for screen plots and small files.
#ifndef TMOP_QUALITY_SVG_CANVAS_H_
#define TMOP_QUALITY_SVG_CANVAS_H_

#include <string>

namespace tmop {

class SvgCanvas {
 public:
  SvgCanvas(double width, double height);

  void rect(double x, double y, double w, double h, const std::string& fill,
            const std::string& stroke = "none", double opacity = 1);
  void line(double x1, double y1, double x2, double y2, const std::string& stroke,
            double width = 1);
  // xy: n points as x0 y0 x1 y1 ...
  void polygon(const double* xy, int n, const std::string& fill, const std::string& stroke,
               double stroke_width);
  void circle(double cx, double cy, double r, const std::string& fill, double opacity = 1);
  // anchor: "start", "middle" or "end". rotate: degrees about (x, y).
  void text(double x, double y, const std::string& s, double size = 12,
            const std::string& anchor = "start", double rotate = 0);

  // The document: XML declaration, <svg> with a white background, the shapes, </svg>.
  std::string finish() const;

 private:
  double width_, height_;
  std::string body_;
};

// "#rrggbb" for r, g, b in [0, 1] (clamped).
std::string svg_rgb(double r, double g, double b);

}  // namespace tmop

#endif  // TMOP_QUALITY_SVG_CANVAS_H_

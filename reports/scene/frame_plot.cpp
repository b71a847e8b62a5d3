#include "reports/scene/frame_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "reports/common/plot.hpp"

namespace stoneskip {

namespace {

// The least of 1, 2, 5 × 10^k at or above x > 0: a tick step that leaves at most about four labels
// on a narrow axis.
double nice_step(double x) {
  if (!(x > 0)) return 1;
  const double p = std::pow(10.0, std::floor(std::log10(x)));
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= x * (1 - 1e-12)) return m * p;
  return 10 * p;
}

// The pond map's plot box in pixels: gnuplot keeps the pond's aspect (`size ratio -1`) inside its
// panel less the room for tick and axis labels (about 110 px across, 90 px down).
struct MapBox {
  double w_px = 0, h_px = 0;
};
MapBox map_box(const FramePlot& p, bool side) {
  const double panel_w = (side ? 0.44 : 0.5) * p.width_px, panel_h = (side ? 0.94 : 1.0) * p.height_px;
  const double avail_w = std::max(1.0, panel_w - 110), avail_h = std::max(1.0, panel_h - 90);
  const double xs = p.pond_x1_m - p.pond_x0_m, ys = p.pond_y1_m - p.pond_y0_m;
  if (!(xs > 0 && ys > 0)) return {avail_w, avail_h};
  MapBox b{avail_w, avail_w * ys / xs};
  if (b.h_px > avail_h) b = {avail_h * xs / ys, avail_h};
  return b;
}

// The 3-D panel's ticks on one axis of its window [lo, hi]: "start, step, end" at multiples of a
// step of about a fifth of the span, none within a tenth of the span of the end `near_corner`
// names. Seen at `set view 52, 28`, the x axis ends (x = hi) where the y axis starts (y = lo):
// gnuplot's own ticks put a label of each there, printed into one another ("0.550.15").
std::string window_tics(double lo, double hi, bool corner_at_hi) {
  const double span = hi - lo;
  if (!(span > 0)) return "auto";
  const double step = nice_step(span / 5);
  const double from = corner_at_hi ? lo : lo + 0.1 * span, to = corner_at_hi ? hi - 0.1 * span : hi;
  const double first = std::ceil(from / step - 1e-9) * step, last = std::floor(to / step + 1e-9) * step;
  if (first > last) return "auto";
  // The end a quarter step past the last tick: a sum of steps that lands 1 ulp beyond it is kept.
  char t[96];  // %g: steps of micrometres print as such, not as 0
  std::snprintf(t, sizeof t, "%.9g, %.9g, %.9g", first == 0 ? 0.0 : first, step, last + 0.25 * step);
  return t;
}

// Room for a tick label: 25 px up the y axis and the colour bar (a line of text and a gap), 70 px
// along the x axis ("-0.15" and a gap). A side with room for kRoomyTicks labels or more keeps
// gnuplot's own ticks; a shorter one (a long narrow pond) gets as many as fit, or one.
constexpr double kLabelHeightPx = 25, kLabelWidthPx = 70, kRoomyTicks = 4;

}  // namespace

std::string frame_plot_commands(const FramePlot& p) {
  std::ostringstream g;
  g.precision(9);
  const double s = p.scale_m > 0 ? p.scale_m : 1e-3;
  const std::string stone_pt = p.stone_sunk ? "pt 6 ps 1.6 lw 2" : "pt 7 ps 1.4";
  // With the side view the panels are placed by hand (screen fractions, below the title's line):
  // the pond 44 %, the 3-D view 34 %, the side view the rest.
  const bool side = !p.side_faces.empty();
  g << "reset\n"
    << "set multiplot" << (side ? "" : " layout 1,2") << " title " << gnuplot_quote(p.title) << "\n"
    << "set palette defined (-1 '#08306b', -0.4 '#4292c6', 0 '#f7fbff', 0.4 '#ef6548', 1 '#7f0000')\n"
    << "set cbrange [" << -s << ":" << s << "]\nset cbtics (";
  // The colour bar is as tall as the map: five labels (mm) where they fit, else ±scale and 0, else 0.
  const MapBox box = map_box(p, side);
  const std::vector<int> halves = box.h_px >= 5 * kLabelHeightPx   ? std::vector<int>{-2, -1, 0, 1, 2}
                                  : box.h_px >= 3 * kLabelHeightPx ? std::vector<int>{-2, 0, 2}
                                                                   : std::vector<int>{0};
  for (std::size_t i = 0; i < halves.size(); ++i) {  // at k halves of the scale, labelled in mm
    const int k = halves[i];
    char label[32];
    std::snprintf(label, sizeof label, "%.2g", k == 0 ? 0.0 : 0.5 * k * 1e3 * s);
    g << (i ? ", " : "") << "'" << label << "' " << 0.5 * k * s;
  }
  g << ")\n";
  if (!p.footnote.empty()) g << "set label 4 " << gnuplot_quote(p.footnote) << " at screen 0.01, screen 0.02 left front\n";
  // Left: the pond from above.
  if (side) g << "set origin 0,0\nset size ratio -1 0.44,0.94\n";
  else g << "set size ratio -1\n";
  // A long narrow pond's map is a strip a few labels high (or wide): as many ticks as fit.
  auto tics = [&](double span, double box_px, double label_px) {
    const double fit = std::floor(box_px / label_px);
    if (fit >= kRoomyTicks) return std::string("auto");
    char step[32];  // %g: a pond of micrometre cells has steps that %f would print as 0
    std::snprintf(step, sizeof step, "%.9g", nice_step(span / std::max(1.0, fit)));
    return std::string(step);
  };
  g << "set xtics " << tics(p.pond_x1_m - p.pond_x0_m, box.w_px, kLabelWidthPx) << "\nset ytics "
    << tics(p.pond_y1_m - p.pond_y0_m, box.h_px, kLabelHeightPx) << "\n";
  g << "set xrange [" << p.pond_x0_m << ":" << p.pond_x1_m << "]\nset yrange [" << p.pond_y0_m << ":"
    << p.pond_y1_m << "]\nset xlabel 'x (m, along the throw)'\nset ylabel 'y (m)'\n"
    // The colour bar's label beside the 3-D panel's own z label would run into it with three panels
    // (the foot line gives the colour's scale in mm).
    << (side ? "unset cblabel\n" : "set cblabel 'z (mm)'\n")
    << "set object 1 rectangle from " << p.near_x0_m << "," << p.near_y0_m << " to " << p.near_x1_m << "," << p.near_y1_m
    << " front fillstyle empty border lc rgb '#555555' dt 2\n";
  if (p.stone_shown)
    g << "set label 1 '' at " << p.stone_x_m << "," << p.stone_y_m << " point " << stone_pt << " lc rgb 'black' front\n";
  g << "plot " << p.top << " with image notitle";
  if (!p.track.empty()) g << ", " << p.track << " with lines lc rgb '#222222' lw 1 notitle";
  if (!p.touches.empty()) g << ", " << p.touches << " with points pt 2 ps 1.2 lc rgb '#222222' notitle";
  g << "\n";
  // Right: the water around the stone, oblique, its heights on the window's own scale.
  const double zs = p.near_z_m > 0 ? p.near_z_m : 2 * s;
  g << "unset object 1\nunset label 1\nunset label 4\nunset colorbox\nset xtics "
    << window_tics(p.near_x0_m, p.near_x1_m, true) << "\nset ytics " << window_tics(p.near_y0_m, p.near_y1_m, false) << "\n";
  if (side) g << "set origin 0.45,0\nset size noratio 0.32,0.94\n";  // clear of the colour bar's label
  else g << "set size noratio\n";
  g << "set view 52, 28, 1, 1\nset xyplane at " << -zs
    << "\nset border 4095 lc rgb '#888888'\nset xrange [" << p.near_x0_m << ":" << p.near_x1_m << "]\nset yrange [" << p.near_y0_m
    << ":" << p.near_y1_m << "]\nset zrange [" << -zs << ":" << zs << "]\nset xlabel 'x (m)'\nset ylabel 'y (m)'\n"
    << "set zlabel 'z (mm)' rotate\n";
  char zt[96];
  std::snprintf(zt, sizeof zt, "set ztics ('%.2g' %.9g, '0' 0, '%.2g' %.9g)\n", -1e3 * zs, -zs, 1e3 * zs, zs);
  g << zt << "set pm3d at s\nunset surface\n";
  const bool in_window = p.stone_x_m >= p.near_x0_m && p.stone_x_m <= p.near_x1_m && p.stone_y_m >= p.near_y0_m && p.stone_y_m <= p.near_y1_m;
  const double stone_z = std::clamp(p.stone_z_m, -zs, zs);
  if (p.stone_shown && in_window)
    g << "set label 2 '' at " << p.stone_x_m << "," << p.stone_y_m << "," << stone_z << " point " << stone_pt
      << " lc rgb 'black' front\n";
  if (p.stone_shown && (!in_window || stone_z != p.stone_z_m)) {  // say where the box cannot show it
    char note[160];
    const double h = p.stone_z_m;
    std::snprintf(note, sizeof note, "stone's centre: %.3g cm %s the still level%s", 100 * std::abs(h), h >= 0 ? "above" : "below",
                  in_window ? (h >= 0 ? " (drawn on the box's lid)" : " (drawn on the box's floor)") : ", outside this window");
    g << "set label 3 " << gnuplot_quote(note) << " at screen " << (side ? 0.46 : 0.56) << ", screen 0.06 left front\n";
  }
  g << "splot " << p.near << " with pm3d notitle\n";
  if (side) {
    // Third: the stone from the side, true scale; the water drawn over it, translucent, so that
    // the part under the surface shows as under it.
    g << "unset label 2\nunset label 3\nunset pm3d\nset surface\nset origin 0.76,0.03\nset size ratio -1 0.24,0.88\n"
      << "set border 3 lc rgb '#444444'\nset tics nomirror\nset xtics " << nice_step((p.side_s1_cm - p.side_s0_cm) / 4)
      << "\nset ytics auto\nset xrange [" << p.side_s0_cm << ":"
      << p.side_s1_cm << "]\nset yrange [" << p.side_z0_cm << ":" << p.side_z1_cm << "]\n"
      << "set xlabel 'along the throw (cm)'\nset ylabel 'z (cm)'\n"
      << "set label 5 'side, true scale' at graph 0.03, graph 0.96 left front\n";
    if (!p.side_note.empty()) g << "set label 6 " << gnuplot_quote(p.side_note) << " at graph 0.03, graph 0.06 left front\n";
    g << "plot " << p.side_faces << " with filledcurves closed fc rgb '#8c8c8c' fs solid 1 border lc rgb '#303030' notitle";
    if (!p.side_water.empty())
      g << ", " << p.side_water << " with filledcurves y=" << p.side_z0_cm
        << " fc rgb '#3182bd' fs transparent solid 0.35 noborder notitle, " << p.side_water
        << " with lines lc rgb '#08519c' lw 1.5 notitle";
    g << "\n";
  }
  g << "unset multiplot\n";
  return g.str();
}

}  // namespace stoneskip

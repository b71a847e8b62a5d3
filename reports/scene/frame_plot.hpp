#pragma once
// One frame of a scene drawn by gnuplot, in two panels side by side:
//   left:  the pond seen from above — the surface height as a colour map (blue below, red above
//          the still level, on a fixed symmetric scale), the stone's track so far, where it touched
//          the water, and the stone (a disk, black; hollow once it has sunk);
//   right: an oblique 3-D view of the water in a window around the stone (or where it sank), the
//          heights exaggerated to the window's own scale; the stone inside the box when it is
//          within it, else a line of text saying how high above the water it is;
//   third, when given (the movie's frames): the stone from the side at true scale, with the water's
//          surface along the throw (reports/scene/side_view.hpp).
// The same commands draw the movie's frames (reports/scene/scene_movie.hpp, binary data files)
// and the report's still frames (reports/scene/scene_report.cpp, the stored tables), so the two
// look alike. Only the data clauses differ.
#include <string>

namespace stoneskip {

struct FramePlot {
  // gnuplot data specifications (file and how to read it), each giving x_m y_m z_m:
  std::string top;      // the pond's surface (with image)
  std::string near;     // the window around the stone (with pm3d)
  std::string track;    // x_m y_m of the stone's path so far ("" for none)
  std::string touches;  // x_m y_m of the first touch of each contact so far ("" for none)
  double stone_x_m = 0, stone_y_m = 0, stone_z_m = 0, stone_radius_m = 0.03;
  bool stone_sunk = false;
  bool stone_shown = true;  // false: no stone (coupling none still shows it; a scene without one does not)
  double pond_x0_m = 0, pond_x1_m = 1, pond_y0_m = 0, pond_y1_m = 1;
  double near_x0_m = 0, near_x1_m = 1, near_y0_m = 0, near_y1_m = 1;
  double scale_m = 1e-3;    // colour scale ±scale_m
  double near_z_m = 0;      // the 3-D view's z range ±near_z_m (0: 2 scale_m); the stone is drawn in
                            // the box only when it is there, else a note says where it is
  std::string title;        // "t = 0.500 s"
  std::string footnote;     // a second line at the frame's foot (the scales), "" for none: one long
                            // title was cut at both ends at 640 px
  int width_px = 1280, height_px = 540;
  // The side view (a third panel): its data specifications, each giving s_cm z_cm, "" for none (the
  // report's still frames keep two panels).
  std::string side_faces;   // the stone's faces, closed outlines separated by blank lines
  std::string side_water;   // the surface along the view, left to right
  double side_s0_cm = -1, side_s1_cm = 1, side_z0_cm = -1, side_z1_cm = 1;
  std::string side_note;    // where the still level is when it is outside the window ("" inside)
};

// The gnuplot commands that draw one frame onto the current output (a multiplot of two panels).
std::string frame_plot_commands(const FramePlot& p);

}  // namespace stoneskip

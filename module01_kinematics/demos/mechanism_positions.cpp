// Module 1 demo: the slider-crank and the four-bar drawn at several crank angles.
//
// Configurations come from the closed-form geometry of examples.hpp; the drawing places every
// body point with point_position() (task M01T1) and prints |C(q)| from the assembled
// constraints (tasks M01T2-T5), which must vanish at every drawn pose.
#include <cmath>
#include <iostream>
#include <gnuplot-iostream.h>

#include "demo.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/examples.hpp"
#include "fmbd/planar.hpp"

namespace {

using namespace fmbd;

// Segments of one pose: each body as the polyline through its points, the ground points as
// short hatches. Rows: (x, y, pose index); an empty row separates polylines.
void add_pose(const Model& model, const VecX& q, int pose, demo::Table& table) {
  for (int b = 0; b < model.num_bodies(); ++b) {
    const Vec3 q_b = model.body_coordinates(q, BodyId{b});
    std::vector<Vec2> pts;
    for (const Point& p : model.points())
      if (p.body.index == b) pts.push_back(point_position(q_b, p.s_bar));
    if (pts.size() == 1) {  // a slider block: a small square around its point
      const double h = 0.02;
      for (const Vec2& c : {Vec2(-h, -h), Vec2(h, -h), Vec2(h, h), Vec2(-h, h), Vec2(-h, -h)})
        pts.push_back(pts.front() + Mat2(rotation(q_b(2))) * c);
      pts.erase(pts.begin());
    }
    for (const Vec2& r : pts) table.add({r.x(), r.y(), double(pose)});
    table.add({});
  }
}

void draw(demo::Figure& figure, const demo::Table& table, const std::string& title, int poses) {
  if (!figure.active()) return;
  Gnuplot& gp = figure.gp();
  gp << "set title '" << title << "'\nset size ratio -1\nset xlabel 'x [m]'\nset ylabel 'y [m]'\n"
     << "set cbrange [0:" << poses - 1 << "]\nset cblabel 'pose'\nset palette rgb 33,13,10\nunset key\n"
     << "plot '-' using 1:2:3 with linespoints lw 2 pt 7 ps 0.6 lc palette\n";
  for (const auto& row : table.rows) {
    if (row.empty()) gp << "\n";
    else gp << row[0] << ' ' << row[1] << ' ' << row[2] << '\n';
  }
  gp << "e\n";
}

}  // namespace

int main(int argc, char** argv) {
  return demo::run(argc, argv, "mechanism_positions", [](const demo::Options& options) {
    const int poses = 8;
    demo::Table slider{{"x [m]", "y [m]", "pose [-]"}, {}}, fourbar{{"x [m]", "y [m]", "pose [-]"}, {}};
    examples::SliderCrankParameters sp;
    examples::FourBarParameters fp;
    const Model slider_crank = examples::slider_crank(sp);
    std::cout << "pose  crank angle  |C| slider-crank  |C| four-bar\n";
    for (int k = 0; k < poses; ++k) {
      const double angle = 2 * M_PI * k / poses;
      const VecX q_sc = examples::slider_crank_configuration(sp, angle);
      fp.theta0 = angle;
      const Model four_bar = examples::four_bar(fp);  // its initial guess is the exact pose
      const VecX q_fb = four_bar.initial_guess();
      add_pose(slider_crank, q_sc, k, slider);
      add_pose(four_bar, q_fb, k, fourbar);
      std::printf("%4d  %11.3f  %16.2e  %12.2e\n", k, angle,
                  constraints(slider_crank, q_sc, (angle - sp.A0) / sp.omega).norm(),
                  constraints(four_bar, q_fb, 0.0).norm());
    }
    demo::write_csv(options, "slider_crank_poses", slider);
    demo::write_csv(options, "four_bar_poses", fourbar);
    demo::Figure a(options, "slider_crank_poses", 1000, 500);
    draw(a, slider, "Slider-crank at 8 crank angles (r = 0.1 m, l = 0.3 m)", poses);
    demo::Figure b(options, "four_bar_poses", 900, 700);
    draw(b, fourbar, "Four-bar crank-rocker at 8 crank angles (a, b, c, d = 0.10, 0.30, 0.25, 0.30 m)", poses);
  });
}

#pragma once
// Options of the CVODE reference solution of the stone's equations of motion.
#include <string>

namespace stoneskip {

// bdf:   CVODE BDF (orders 1–5), Newton iteration with a dense direct linear solver and CVODE's
//        finite-difference Jacobian.
// adams: CVODE Adams–Moulton (orders 1–12), Newton-free fixed-point (functional) iteration.
enum class ReferenceMethod { bdf, adams };
const char* to_string(ReferenceMethod m);
bool parse_reference_method(const std::string& s, ReferenceMethod& out);

struct ReferenceOptions {
  ReferenceMethod method = ReferenceMethod::bdf;
  double rtol = 1e-10;
  double atol = 1e-12;          // absolute tolerance on every component (SI units)
  double t_max_s = 10.0;
  double output_dt_s = 1e-3;    // trajectory sampling; located events are always sampled
  long max_steps = 2000000;     // over the whole throw; exceeding it fails the solve
  bool record_trajectory = true;
  // Also restart where a wet face's normal velocity u_i changes sign and where the air flow over
  // the disk reverses (physical convention only: there the force max(u,0)² and u|u| is C¹, not
  // smooth; in the paper convention u² is smooth and nothing is located). Vertex crossings are
  // always located.
  bool locate_switches = true;
  double max_step_s = 0;        // CVODE's largest step; 0: no limit
  // Chattering guard: the solve fails when more than this many events fall within 1 ms.
  int max_events_per_ms = 1000;
};

}  // namespace stoneskip

#pragma once
// The findings of a capture's throw through the coupled scene (capture_scene.hpp), stored as the
// child `scene` of the capture's record (capture_findings.hpp) and rendered by reports/capture:
//   settings         case_file, coupling, convention, stone_description, stencil (texts); nx, ny, cell_m, wave_speed_m_s,
//                    damping_per_s, dt_s, courant, draught_samples, frame_rate_hz, duration_s,
//                    reference_rtol, reference_output_dt_s, quadrature_intervals, quadrature_nodes
//   stone            bounces of the scene, the stepper on still water and CVODE; the contacts
//                    compared (table `contacts`: index, scene/still/reference start and end, exit x,
//                    bounced); max_start_difference_s, max_end_difference_s,
//                    still_max_start_difference_s; verdict `agreement` (rule bounce_agreement: the
//                    scene's bounces against CVODE's); trajectories (tables `scene_path`,
//                    `reference_path`: t_s, x_m, z_m); cost (scene frames, thread CPU, wall; CVODE)
//   waves            compared (0/1) and, when not, `not_compared` (why); else t_s, steps, amplitude_m,
//                    total_m, model_m, path_m, feedback_m, time_m, space_m, quadrature_m (capture_scene.hpp says what
//                    each is), verdict `reference` (rule reference_resolves: is the reference's own
//                    error below the smallest error it is used to measure), table `profile` (x_m,
//                    scene_m, prescribed_m, semi_discrete_m, continuum_m along the grid row nearest
//                    the first contact), row_y_m, the same along the row of the largest
//                    |scene − continuum| (table `worst_profile`, worst_row_y_m, worst_x_m), cost (thread
//                    CPU and wall of the references)
#include <string>

#include "verification/captures/capture_scene.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

// The reference must be this many times more accurate than the smallest error it measures.
constexpr double kReferenceMargin = 10;

Record capture_scene_findings(const CaptureSceneComparison& c, const CaptureSceneOptions& o, const std::string& case_file);

}  // namespace stoneskip

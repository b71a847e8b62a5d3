#include "model/stone/fluid_forces.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "model/stone/pressure_distribution.hpp"
#include "model/stone/triangle_clip.hpp"
#include "model/stone/water_laws.hpp"

namespace stoneskip {

namespace {

// What the first pass over the faces leaves for the distributed pressure: each face's world
// normal R n_i (computed once per call) and its geometric wetted polygon with area and centroid
// (count 0: dry). Reused between calls: no allocation in a step loop once grown to the stone.
struct FaceScratch {
  Vec3 normal;
  bool has_normal = false;  // normal computed (only for faces that reach the water)
  bool fully_wet = false;   // every vertex at depth ≥ 0: the polygon is the whole triangle
  ClippedPolygon wetted;
  ClippedArea area;
};

// The law's pressure redistributed along the wetted length (model/stone/pressure_distribution.hpp):
// on face i, p(x) = K p_i w(ξ(x)) over its wetted polygon (below the raised waterline for the
// Wagner variant, on the stone's underside: on_underside in pressure_distribution.hpp), with p_i
// the law evaluated at the face's centre of pressure x_i = ∫w x dA / ∫w dA (so the face's power
// −K p_i W_i u(x_i) is never positive) and K such that Σ K p_i W_i is the law's total force on the
// geometric wetted area. F_i = −K p_i W_i n_i acts at x_i. Below planing speed
// the weight is blended with a uniform one, w_β = (1 − β) + β w (planing_share): W_i and ∫w x dA
// are then (1 − β) S_i + β W_i and (1 − β) S_i c_i + β ∫w x dA, S_i and c_i the polygon's area
// and centroid.
void add_distributed_loads(const Stone& stone, const Environment& env, const RigidState& s, const Mat3& R,
                           const Vec3& omega, const std::vector<Vec3>& world, const std::vector<double>& depth,
                           std::vector<FaceScratch>& scratch, double law_total_N, WaterLoads& out,
                           std::vector<FacePush>* pushes, const LoadMode* mode) {
  struct FaceLoad {
    double weight_m2;
    Vec3 centre_m;
    double pressure_Pa;
  };
  // Each face's loaded polygon (null: none): its geometric one in scratch, or one cut below the
  // raised waterline into raised_polys (pointers, not copies: copying every face's polygon cost
  // about 2 % of a contact right-hand side, BM_ContactRhsDefaultModel, 6 December).
  thread_local std::vector<const ClippedPolygon*> polys;
  thread_local std::vector<ClippedPolygon> raised_polys;
  thread_local std::vector<ClippedArea> poly_areas;
  thread_local std::vector<FaceLoad> faces;
  const auto& tris = stone.body_mesh.triangles;
  const std::size_t nt = tris.size();
  const double rise = waterline_rise_m(env.pressure_distribution, out.deepest_depth_m);
  const int side = mode && mode->underside != 0 ? mode->underside : underside_side(R);
  if (polys.size() < nt) polys.resize(nt);
  if (raised_polys.size() < nt) raised_polys.resize(nt);
  if (poly_areas.size() < nt) poly_areas.resize(nt);
  if (faces.size() < nt) faces.resize(nt);
  // The wetted length is that of the loaded region: faces advancing into the water (a receding
  // trailing rim or a dry-side face under the raised waterline would lengthen it for nothing).
  WettedSpanBuilder span_builder(s.velocity_m_s);
  for (std::size_t i = 0; i < nt; ++i) {
    polys[i] = nullptr;
    FaceScratch& f = scratch[i];
    ClippedArea c;
    const auto& t = tris[i];
    const ClippedPolygon* poly = &f.wetted;
    if (rise == 0 || f.fully_wet || !on_underside(stone.face_normals_body[i], side)) {
      // The same polygon as below the geometric waterline (that waterline, a face wholly under it,
      // or a face the rise does not wet: off the underside).
      c = f.area;
    } else {
      const double d0 = depth[t[0]] + rise, d1 = depth[t[1]] + rise, d2 = depth[t[2]] + rise;
      if (d0 < 0 && d1 < 0 && d2 < 0) continue;
      if (!f.has_normal) f.normal = R * stone.face_normals_body[i];  // dry below the geometric waterline
      raised_polys[i] = clip_submerged_polygon(world[t[0]], world[t[1]], world[t[2]], d0, d1, d2);
      poly = &raised_polys[i];
      c = area_of(*poly, f.normal);
    }
    if (poly->count == 0) continue;
    poly_areas[i] = c;
    // A face sliding in its own plane to round-off (u below 1e-9 of its speed) is not advancing
    // (u > 1e-9 |v_c| compared squared: no square root).
    const Vec3 vc = s.velocity_m_s + omega.cross(c.centroid_m - s.position_m);
    const double u = vc.dot(f.normal);
    const char held = mode && i < mode->loaded_faces.size() ? mode->loaded_faces[i] : LoadMode::kDecide;
    const bool loaded = held != LoadMode::kDecide ? held != 0 : u > 0 && u * u > 1e-18 * vc.squaredNorm();
    if (c.area_m2 > 0 && loaded) {
      span_builder.add(*poly);
      polys[i] = poly;
    }
  }
  const WettedSpan span = span_builder.span();
  const double k = power_weight_exponent(kSavitskyCentreFraction);
  const double U = s.velocity_m_s.norm();
  // Without a span (no horizontal velocity, or none of the loaded region along it) the weight is
  // the uniform one on the same polygons: the limit of w_β as β → 0, so the loads stay continuous.
  const double beta =
      span.valid() ? planing_share(s.velocity_m_s, env.gravity_m_s2, 2 * stone.disk_radius_m) : 0;
  double distributed_N = 0;  // Σ p_i W_i
  for (std::size_t i = 0; i < nt; ++i) {
    faces[i].pressure_Pa = 0;
    if (!polys[i]) continue;
    WeightedIntegrals w;
    if (beta > 0) w = integrate_weight(*polys[i], span, k, scratch[i].normal);
    if (beta < 1) {
      const ClippedArea& a = poly_areas[i];
      w.weight_m2 = (1 - beta) * a.area_m2 + beta * w.weight_m2;
      w.moment_m3 = ((1 - beta) * a.area_m2) * a.centroid_m + beta * w.moment_m3;
    }
    if (!(w.weight_m2 > 0)) continue;
    const Vec3 centre = w.moment_m3 * (1 / w.weight_m2);
    const Vec3& n = scratch[i].normal;
    const double p = law_pressure_Pa(env, (s.velocity_m_s + omega.cross(centre - s.position_m)).dot(n), U);
    if (p == 0) continue;  // a NaN pressure passes on: the solvers fail on it, saying where
    faces[i] = {w.weight_m2, centre, p};
    distributed_N += p * w.weight_m2;
  }
  if (distributed_N == 0) {
    // No face pushes at its centre of pressure (a single wet point, faces that only just advance):
    // the pressure is uniform on each face's geometric wetted polygon.
    Environment uniform = env;
    uniform.pressure_distribution = PressureDistribution::uniform;
    const WaterLoads u = water_loads_from_depths(stone, uniform, s, R, omega, world, depth, pushes);
    out.force_N = u.force_N;
    out.torque_N_m = u.torque_N_m;
    return;
  }
  const double scale = law_total_N / distributed_N;  // K
  for (std::size_t i = 0; i < nt; ++i) {
    if (faces[i].pressure_Pa == 0) continue;
    const Vec3 F = -(scale * faces[i].pressure_Pa * faces[i].weight_m2) * scratch[i].normal;
    out.force_N += F;
    out.torque_N_m += (faces[i].centre_m - s.position_m).cross(F);
    if (pushes) pushes->push_back({*polys[i], F});
  }
}

}  // namespace

WaterLoads water_loads_from_depths(const Stone& stone, const Environment& env, const RigidState& s, const Mat3& R,
                                   const Vec3& omega, const std::vector<Vec3>& world, const std::vector<double>& depth,
                                   std::vector<FacePush>* pushes, const LoadMode* mode) {
  WaterLoads out;
  if (pushes) pushes->clear();
  const int nv = static_cast<int>(world.size());
  out.vertex_count = nv;
  double deepest = -1e300;
  for (int k = 0; k < nv; ++k) {
    if (std::isnan(depth[k])) {
      // A NaN surface or state: NaN loads, which the solvers fail on, saying where (std::max would
      // skip the NaN, and a stone over a NaN field would fly on as if over no water).
      out.force_N = out.torque_N_m = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
      out.deepest_depth_m = depth[k];
      return out;
    }
    deepest = std::max(deepest, depth[k]);
    if (depth[k] > 0) ++out.submerged_vertices;
  }
  out.deepest_depth_m = deepest;
  if (deepest <= 0) return out;

  const bool paper = env.convention == Convention::paper;
  const bool distributed = !paper && env.pressure_distribution != PressureDistribution::uniform;
  const double U = s.velocity_m_s.norm();  // the planing law's speed (model/stone/water_laws.hpp)
  double law_total_N = 0;                  // Σ p_i S_i of the law on the geometric wetted area
  const auto& tris = stone.body_mesh.triangles;
  const std::size_t nt = tris.size();
  // Each call owns its scratch while it runs (the uniform fallback of the distributed pressure
  // calls back in here, after its caller's last use of its scratch).
  thread_local std::vector<FaceScratch> scratch;
  if (scratch.size() < nt) scratch.resize(nt);
  for (std::size_t i = 0; i < nt; ++i) {
    const auto& t = tris[i];
    FaceScratch& f = scratch[i];
    f.wetted.count = 0;
    f.area = ClippedArea{};
    f.has_normal = f.fully_wet = false;
    const double d0 = depth[t[0]], d1 = depth[t[1]], d2 = depth[t[2]];
    if (d0 < 0 && d1 < 0 && d2 < 0) continue;  // dry: nothing below the surface
    f.normal = R * stone.face_normals_body[i];
    f.has_normal = true;
    // Area and centroid exactly as clip_submerged computes them (bit for bit: the uniform and
    // paper laws' loads, whose long chaotic runs are stored as baselines, stay the same), the
    // polygon kept for the distributed pressure and the pushes.
    if (d0 >= 0 && d1 >= 0 && d2 >= 0) {
      f.fully_wet = true;  // wholly under water: the triangle itself
      f.wetted.vertices[0] = world[t[0]];
      f.wetted.vertices[1] = world[t[1]];
      f.wetted.vertices[2] = world[t[2]];
      f.wetted.count = 3;
      f.area = clip_submerged(world[t[0]], world[t[1]], world[t[2]], d0, d1, d2);
    } else {
      f.wetted = clip_submerged_polygon(world[t[0]], world[t[1]], world[t[2]], d0, d1, d2);
      f.area = area_of(f.wetted);
    }
    const ClippedArea& c = f.area;
    if (c.area_m2 <= 0) continue;
    ++out.wet_triangles;
    out.wetted_area_m2 += c.area_m2;
    const Vec3& n = f.normal;
    const Vec3 r = c.centroid_m - s.position_m;  // lever arm (model/README.md §1.4 step 3)
    if (paper) {
      // Lee & Baek 2013 Eq. 1 as printed (v + r × ω), Eq. 2 on every submerged face, Eq. 3 F × r.
      const Vec3 F = printed_face_force_N(env, n, s.velocity_m_s + r.cross(omega), c.area_m2);
      out.force_N += F;
      out.torque_N_m += F.cross(r);
      if (pushes) pushes->push_back({f.wetted, F});
      continue;
    }
    // Physical: v_i = v + ω × r_i; the law's pressure, zero unless the face advances into the water.
    const double p = law_pressure_Pa(env, (s.velocity_m_s + omega.cross(r)).dot(n), U);
    if (p == 0) continue;  // a NaN pressure passes on: the solvers fail on it, saying where
    if (distributed) {
      law_total_N += p * c.area_m2;
      continue;
    }
    const Vec3 F = -(p * c.area_m2) * n;
    out.force_N += F;
    out.torque_N_m += r.cross(F);  // Eq. 3, physical order
    if (pushes) pushes->push_back({f.wetted, F});
  }
  if (distributed && law_total_N != 0)
    add_distributed_loads(stone, env, s, R, omega, world, depth, scratch, law_total_N, out, pushes, mode);
  return out;
}

WaterLoads water_loads(const Stone& stone, const Environment& env, const RigidState& s, const WaterSurface* surface,
                       std::vector<FacePush>* pushes, const LoadMode* mode) {
  // Still water: a stone whose bounding sphere is above z = 0 cannot touch it.
  if (!surface && s.position_m.z() - stone.bounding_radius_m > 0) {
    if (pushes) pushes->clear();
    WaterLoads out;
    out.vertex_count = static_cast<int>(stone.body_mesh.vertices.size());
    out.deepest_depth_m = -(s.position_m.z() - stone.bounding_radius_m);
    return out;
  }
  const Mat3 R = s.orientation.normalized().toRotationMatrix();
  const Vec3 omega = R * (stone.inertia_body_inv * (R.transpose() * s.angular_momentum_kg_m2_s));

  // Vertex positions and signed depths d_j = η(x_j, y_j) − z_j (model/README.md §1.4 step 1). The buffers are
  // reused between calls: no allocation in a step loop once they have grown.
  thread_local std::vector<Vec3> world;
  thread_local std::vector<double> depth;
  const auto& verts = stone.body_mesh.vertices;
  const int nv = static_cast<int>(verts.size());
  world.resize(nv);
  depth.resize(nv);
  for (int k = 0; k < nv; ++k) {
    world[k] = s.position_m + R * verts[k];
    const double eta = surface ? surface->height_m(world[k].x(), world[k].y()) : 0.0;
    depth[k] = eta - world[k].z();
  }
  return water_loads_from_depths(stone, env, s, R, omega, world, depth, pushes, mode);
}

AirLoads air_loads(const Stone& stone, const Environment& env, const RigidState& s) {
  AirLoads out;
  const Vec3 n = s.orientation.normalized() * Vec3::UnitZ();  // disk normal: body z in world
  const double u = s.velocity_m_s.dot(n);
  const double k = env.air_coefficient * env.air_density_kg_m3 * stone.disk_area_m2;
  // Lee & Baek 2013 Eq. 6 prints (v·n)²: always along −n; physical u|u| opposes the motion.
  const double mag = env.convention == Convention::paper ? u * u : u * std::abs(u);
  out.force_N = -k * mag * n;
  return out;
}

}  // namespace stoneskip

#include "model/stone/load_switches.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "model/stone/pressure_distribution.hpp"
#include "model/stone/triangle_clip.hpp"

namespace stoneskip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The corners of the polygon clip_submerged_polygon cuts from triangle t at depths d (raised or
// not), in its order (Sutherland–Hodgman against d ≥ 0).
int corners_of(const std::array<int, 3>& t, const double d[3], bool raised, PolygonCorner out[4]) {
  int n = 0;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const bool in_i = d[i] >= 0, in_j = d[j] >= 0;
    if (in_i) out[n++] = {t[i], -1};
    if (in_i != in_j) out[n++] = {std::min(t[i], t[j]), std::max(t[i], t[j]), raised};
  }
  return n;
}

}  // namespace

LoadSwitches::LoadSwitches(const Stone& stone, const Environment& env, const WaterSurface* surface)
    : stone_(stone), env_(env), surface_(surface) {
  active_ = env.convention == Convention::physical && env.pressure_distribution != PressureDistribution::uniform;
  nv_ = static_cast<int>(stone.body_mesh.vertices.size());
  nf_ = static_cast<int>(stone.body_mesh.triangles.size());
}

void LoadSwitches::reset(const RigidState& s, std::vector<double>& g) {
  Mode recorded;
  compute(s, &recorded, recorded, g);
  mode_ = std::move(recorded);
}

void LoadSwitches::evaluate(const RigidState& s, std::vector<double>& g) const { compute(s, nullptr, mode_, g); }

LoadSwitches::Kind LoadSwitches::kind(int k) const {
  if (k < nv_) return Kind::raised_crossing;
  if (k < 2 * nv_) return Kind::deepest_vertex;
  if (k < 2 * nv_ + nf_) return Kind::loaded_face;
  if (k < 2 * nv_ + 2 * nf_) return Kind::centre_of_pressure;
  if (k == 2 * nv_ + 2 * nf_) return Kind::planing_share;
  if (k == 2 * nv_ + 2 * nf_ + 1) return Kind::underside_flip;
  return k < 2 * nv_ + 2 * nf_ + 2 + static_cast<int>(mode_.corners.size()) ? Kind::span_start : Kind::span_end;
}

// With record, the mode is recorded from s as the faces are visited and the values are those in it
// (held is then *record).
void LoadSwitches::compute(const RigidState& s, Mode* record, const Mode& held, std::vector<double>& g) const {
  g.assign(2 * nv_ + 2 * nf_ + 2, kNaN);
  if (!active_) return;
  // The state's geometry exactly as water_loads computes it (fluid_forces.cpp).
  const Mat3 R = s.orientation.normalized().toRotationMatrix();
  const Vec3 omega = R * (stone_.inertia_body_inv * (R.transpose() * s.angular_momentum_kg_m2_s));
  const auto& verts = stone_.body_mesh.vertices;
  std::vector<Vec3> world(nv_);
  std::vector<double> depth(nv_);
  int deepest = -1;
  for (int k = 0; k < nv_; ++k) {
    world[k] = s.position_m + R * verts[k];
    const double eta = surface_ ? surface_->height_m(world[k].x(), world[k].y()) : 0.0;
    depth[k] = eta - world[k].z();
    if (deepest < 0 || depth[k] > depth[deepest]) deepest = k;
  }
  if (deepest < 0) return;
  const bool wagner = env_.pressure_distribution == PressureDistribution::savitsky_wagner;
  // The Wagner rise is 0 out of the water, where the raised waterline is the surface (its crossings
  // are stone_events.hpp's) and which vertex is deepest does not matter: those switches are watched
  // only in a mode taken in contact (a contact's start is a crossing, located by the caller).
  if (record) {
    record->deepest = depth[deepest] > 0 ? deepest : -1;
    record->loads.loaded_faces.assign(nf_, LoadMode::kDecide);
    record->loads.underside = wagner ? underside_side(R) : 0;
  }
  const int side = held.loads.underside != 0 ? held.loads.underside : underside_side(R);
  const double rise = waterline_rise_m(env_.pressure_distribution, depth[deepest]);
  std::vector<double> raised(nv_);
  for (int k = 0; k < nv_; ++k) raised[k] = depth[k] + rise;
  if (wagner && held.deepest >= 0) {
    for (int k = 0; k < nv_; ++k) g[k] = raised[k];
    // The deepest vertex of the mode against each other.
    for (int k = 0; k < nv_; ++k)
      if (k != held.deepest) g[nv_ + k] = depth[held.deepest] - depth[k];
    g[2 * nv_ + 2 * nf_ + 1] = R(2, 2);  // the body z axis's vertical part: the underside's side
  }

  // Each face's polygon below the raised waterline (on the underside; elsewhere below the surface)
  // and whether it is loaded (advancing into the water at its centroid), as add_distributed_loads
  // in fluid_forces.cpp decides it.
  const auto& tris = stone_.body_mesh.triangles;
  std::vector<ClippedPolygon> polys(nf_);
  std::vector<ClippedArea> areas(nf_);
  std::vector<char> loaded(nf_, 0);
  std::vector<Vec3> normals(nf_);
  WettedSpanBuilder span_builder(s.velocity_m_s);
  const int face_base = 2 * nv_;
  for (int i = 0; i < nf_; ++i) {
    const auto& t = tris[i];
    const bool up = on_underside(stone_.face_normals_body[i], side);
    const std::vector<double>& di = up ? raised : depth;
    const double d[3] = {di[t[0]], di[t[1]], di[t[2]]};
    if (d[0] < 0 && d[1] < 0 && d[2] < 0) continue;
    normals[i] = R * stone_.face_normals_body[i];
    polys[i] = clip_submerged_polygon(world[t[0]], world[t[1]], world[t[2]], d[0], d[1], d[2]);
    const ClippedArea& c = areas[i] = area_of(polys[i], normals[i]);
    if (!(c.area_m2 > 0)) continue;
    const Vec3 vc = s.velocity_m_s + omega.cross(c.centroid_m - s.position_m);
    const double u = vc.dot(normals[i]);
    // The loads' test, u > 1e-9 |v_c| (fluid_forces.cpp), as a sign: a root at u = 0 instead would
    // leave a step cut back to it short of the switch, and the region held wrong over the next.
    g[face_base + i] = u - 1e-9 * vc.norm();
    // Recording: loaded as the loads decide it from the state; else as the mode holds it.
    const bool from_state = u > 0 && u * u > 1e-18 * vc.squaredNorm();
    const char held_i =
        i < static_cast<int>(held.loads.loaded_faces.size()) ? held.loads.loaded_faces[i] : LoadMode::kDecide;
    const bool is_loaded = record || held_i == LoadMode::kDecide ? from_state : held_i != 0;
    if (record) record->loads.loaded_faces[i] = is_loaded ? 1 : 0;
    if (is_loaded) {
      loaded[i] = 1;
      span_builder.add(polys[i]);
      if (record) {
        PolygonCorner corners[4];
        const int n = corners_of(t, d, up, corners);
        for (int k = 0; k < n; ++k) {
          bool seen = false;
          for (const PolygonCorner& c0 : record->corners) seen = seen || c0 == corners[k];
          if (!seen) record->corners.push_back(corners[k]);
        }
      }
    }
  }
  const WettedSpan span = span_builder.span();
  const double vh = std::hypot(s.velocity_m_s.x(), s.velocity_m_s.y());
  const double beam_m = 2 * stone_.disk_radius_m;
  if (span.valid()) g[2 * nv_ + 2 * nf_] = vh - std::sqrt(env_.gravity_m_s2 * beam_m);  // planing_share's ramp end
  const double beta = span.valid() ? planing_share(s.velocity_m_s, env_.gravity_m_s2, beam_m) : 0;

  // Each loaded face's centre of pressure and its normal velocity there.
  const double k = power_weight_exponent(kSavitskyCentreFraction);
  for (int i = 0; i < nf_; ++i) {
    if (!loaded[i]) continue;
    WeightedIntegrals w;
    if (beta > 0) w = integrate_weight(polys[i], span, k, normals[i]);
    if (beta < 1) {
      const ClippedArea& a = areas[i];
      w.weight_m2 = (1 - beta) * a.area_m2 + beta * w.weight_m2;
      w.moment_m3 = ((1 - beta) * a.area_m2) * a.centroid_m + beta * w.moment_m3;
    }
    if (!(w.weight_m2 > 0)) continue;
    const Vec3 centre = w.moment_m3 * (1 / w.weight_m2);
    g[2 * nv_ + nf_ + i] = (s.velocity_m_s + omega.cross(centre - s.position_m)).dot(normals[i]);
  }

  const int nc = static_cast<int>(held.corners.size());
  g.resize(g.size() + 2 * nc, kNaN);
  // The span's ends: each corner of the mode against the mode's trailing and leading corner, along
  // the state's own horizontal direction; an edge's corner extended along the edge's line.
  if (vh > 1e-6 && (record || nc > 0)) {
    const Vec3 dir(s.velocity_m_s.x() / vh, s.velocity_m_s.y() / vh, 0);
    auto along = [&](const PolygonCorner& c) {
      if (c.b < 0) return dir.dot(world[c.a]);
      const std::vector<double>& dc = c.raised ? raised : depth;
      const double da = dc[c.a], db = dc[c.b];
      if (da == db) return kNaN;
      return dir.dot(world[c.a] + (da / (da - db)) * (world[c.b] - world[c.a]));
    };
    if (record) {
      double lo = 0, hi = 0;
      for (int c = 0; c < static_cast<int>(record->corners.size()); ++c) {
        const double sc = along(record->corners[c]);
        if (!std::isfinite(sc)) continue;
        if (record->start < 0 || sc < lo) record->start = c, lo = sc;
        if (record->end < 0 || sc > hi) record->end = c, hi = sc;
      }
    }
    if (nc > 0 && held.start >= 0 && held.end >= 0) {
      const double lo = along(held.corners[held.start]), hi = along(held.corners[held.end]);
      const int base = 2 * nv_ + 2 * nf_ + 2;
      for (int c = 0; c < nc; ++c) {
        const double sc = along(held.corners[c]);
        if (c != held.start) g[base + c] = sc - lo;
        if (c != held.end) g[base + nc + c] = hi - sc;
      }
    }
  }
}

}  // namespace stoneskip

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

void LoadSwitches::vertices(const RigidState& s, Vertices& v) const {
  v.R = s.orientation.normalized().toRotationMatrix();
  v.omega = v.R * (stone_.inertia_body_inv * (v.R.transpose() * s.angular_momentum_kg_m2_s));
  const auto& verts = stone_.body_mesh.vertices;
  v.world.resize(nv_);
  v.depth.resize(nv_);
  v.raised.resize(nv_);
  v.deepest = -1;
  for (int k = 0; k < nv_; ++k) {
    v.world[k] = s.position_m + v.R * verts[k];
    const double eta = surface_ ? surface_->height_m(v.world[k].x(), v.world[k].y()) : 0.0;
    v.depth[k] = eta - v.world[k].z();
    if (v.deepest < 0 || v.depth[k] > v.depth[v.deepest]) v.deepest = k;
  }
  if (v.deepest < 0) return;
  const double rise = waterline_rise_m(env_.pressure_distribution, v.depth[v.deepest]);
  for (int k = 0; k < nv_; ++k) v.raised[k] = v.depth[k] + rise;
}

bool LoadSwitches::cut_face(int i, int side, const RigidState& s, const Vertices& v, FaceCut& f) const {
  const auto& t = stone_.body_mesh.triangles[i];
  f.up = on_underside(stone_.face_normals_body[i], side);
  const std::vector<double>& di = f.up ? v.raised : v.depth;
  f.d[0] = di[t[0]];
  f.d[1] = di[t[1]];
  f.d[2] = di[t[2]];
  if (f.d[0] < 0 && f.d[1] < 0 && f.d[2] < 0) return false;
  f.normal = v.R * stone_.face_normals_body[i];
  f.poly = clip_submerged_polygon(v.world[t[0]], v.world[t[1]], v.world[t[2]], f.d[0], f.d[1], f.d[2]);
  f.area = area_of(f.poly, f.normal);
  if (!(f.area.area_m2 > 0)) return false;
  f.vc = s.velocity_m_s + v.omega.cross(f.area.centroid_m - s.position_m);
  f.u = f.vc.dot(f.normal);
  return true;
}

double LoadSwitches::along(const PolygonCorner& c, const Vec3& dir, const Vertices& v) const {
  if (c.b < 0) return dir.dot(v.world[c.a]);
  const std::vector<double>& dc = c.raised ? v.raised : v.depth;
  const double da = dc[c.a], db = dc[c.b];
  if (da == db) return kNaN;
  return dir.dot(v.world[c.a] + (da / (da - db)) * (v.world[c.b] - v.world[c.a]));
}

// With record, the mode is recorded from s as the faces are visited and the values are those in it
// (held is then *record).
void LoadSwitches::compute(const RigidState& s, Mode* record, const Mode& held, std::vector<double>& g) const {
  g.assign(2 * nv_ + 2 * nf_ + 2, kNaN);
  if (!active_) return;
  // The state's geometry exactly as water_loads computes it (fluid_forces.cpp).
  Vertices& v = vertices_;
  vertices(s, v);
  const int deepest = v.deepest;
  if (deepest < 0) return;
  const Mat3& R = v.R;
  const bool wagner = env_.pressure_distribution == PressureDistribution::savitsky_wagner;
  // The Wagner rise is 0 out of the water, where the raised waterline is the surface (its crossings
  // are stone_events.hpp's) and which vertex is deepest does not matter: those switches are watched
  // only in a mode taken in contact (a contact's start is a crossing, located by the caller).
  if (record) {
    record->deepest = v.depth[deepest] > 0 ? deepest : -1;
    record->loads.loaded_faces.assign(nf_, LoadMode::kDecide);
    record->loads.underside = wagner ? underside_side(R) : 0;
  }
  const int side = held.loads.underside != 0 ? held.loads.underside : underside_side(R);
  if (wagner && held.deepest >= 0) {
    for (int k = 0; k < nv_; ++k) g[k] = v.raised[k];
    // The deepest vertex of the mode against each other.
    for (int k = 0; k < nv_; ++k)
      if (k != held.deepest) g[nv_ + k] = v.depth[held.deepest] - v.depth[k];
    g[2 * nv_ + 2 * nf_ + 1] = R(2, 2);  // the body z axis's vertical part: the underside's side
  }

  // Each face's polygon below the raised waterline (on the underside; elsewhere below the surface)
  // and whether it is loaded (advancing into the water at its centroid), as add_distributed_loads
  // in fluid_forces.cpp decides it.
  const auto& tris = stone_.body_mesh.triangles;
  faces_.resize(nf_);
  loaded_.assign(nf_, 0);
  WettedSpanBuilder span_builder(s.velocity_m_s);
  const int face_base = 2 * nv_;
  for (int i = 0; i < nf_; ++i) {
    FaceCut& f = faces_[i];
    if (!cut_face(i, side, s, v, f)) continue;
    const double u = f.u;
    const Vec3& vc = f.vc;
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
      loaded_[i] = 1;
      span_builder.add(f.poly);
      if (record) {
        PolygonCorner corners[4];
        const int n = corners_of(tris[i], f.d, f.up, corners);
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
    if (!loaded_[i]) continue;
    const FaceCut& f = faces_[i];
    WeightedIntegrals w;
    if (beta > 0) w = integrate_weight(f.poly, span, k, f.normal);
    if (beta < 1) {
      const ClippedArea& a = f.area;
      w.weight_m2 = (1 - beta) * a.area_m2 + beta * w.weight_m2;
      w.moment_m3 = ((1 - beta) * a.area_m2) * a.centroid_m + beta * w.moment_m3;
    }
    if (!(w.weight_m2 > 0)) continue;
    const Vec3 centre = w.moment_m3 * (1 / w.weight_m2);
    g[2 * nv_ + nf_ + i] = (s.velocity_m_s + v.omega.cross(centre - s.position_m)).dot(f.normal);
  }

  const int nc = static_cast<int>(held.corners.size());
  g.resize(g.size() + 2 * nc, kNaN);
  // The span's ends: each corner of the mode against the mode's trailing and leading corner, along
  // the state's own horizontal direction; an edge's corner extended along the edge's line.
  if (vh > 1e-6 && (record || nc > 0)) {
    const Vec3 dir(s.velocity_m_s.x() / vh, s.velocity_m_s.y() / vh, 0);
    if (record) {
      double lo = 0, hi = 0;
      for (int c = 0; c < static_cast<int>(record->corners.size()); ++c) {
        const double sc = along(record->corners[c], dir, v);
        if (!std::isfinite(sc)) continue;
        if (record->start < 0 || sc < lo) record->start = c, lo = sc;
        if (record->end < 0 || sc > hi) record->end = c, hi = sc;
      }
    }
    if (nc > 0 && held.start >= 0 && held.end >= 0) {
      const double lo = along(held.corners[held.start], dir, v), hi = along(held.corners[held.end], dir, v);
      const int base = 2 * nv_ + 2 * nf_ + 2;
      for (int c = 0; c < nc; ++c) {
        const double sc = along(held.corners[c], dir, v);
        if (c != held.start) g[base + c] = sc - lo;
        if (c != held.end) g[base + nc + c] = hi - sc;
      }
    }
  }
}

double LoadSwitches::value(const RigidState& s, int k) const {
  if (!active_ || k < 0) return kNaN;
  const Mode& held = mode_;
  const int nc = static_cast<int>(held.corners.size());
  if (k >= 2 * nv_ + 2 * nf_ + 2 + 2 * nc) return kNaN;
  const Kind what = kind(k);
  if (what == Kind::centre_of_pressure || what == Kind::planing_share) {
    // Both depend on the whole loaded region: evaluate's own computation.
    compute(s, nullptr, held, values_);
    return values_[k];
  }
  Vertices& v = vertices_;
  vertices(s, v);
  if (v.deepest < 0) return kNaN;
  const bool wagner = env_.pressure_distribution == PressureDistribution::savitsky_wagner;
  switch (what) {
    case Kind::raised_crossing: return wagner && held.deepest >= 0 ? v.raised[k] : kNaN;
    case Kind::deepest_vertex: {
      const int j = k - nv_;
      return wagner && held.deepest >= 0 && j != held.deepest ? v.depth[held.deepest] - v.depth[j] : kNaN;
    }
    case Kind::underside_flip: return wagner && held.deepest >= 0 ? v.R(2, 2) : kNaN;
    case Kind::loaded_face: {
      const int side = held.loads.underside != 0 ? held.loads.underside : underside_side(v.R);
      FaceCut f;
      if (!cut_face(k - 2 * nv_, side, s, v, f)) return kNaN;
      return f.u - 1e-9 * f.vc.norm();
    }
    case Kind::span_start:
    case Kind::span_end: {
      const double vh = std::hypot(s.velocity_m_s.x(), s.velocity_m_s.y());
      if (!(vh > 1e-6 && nc > 0 && held.start >= 0 && held.end >= 0)) return kNaN;
      const Vec3 dir(s.velocity_m_s.x() / vh, s.velocity_m_s.y() / vh, 0);
      const int base = 2 * nv_ + 2 * nf_ + 2;
      if (what == Kind::span_start) {
        const int c = k - base;
        return c != held.start ? along(held.corners[c], dir, v) - along(held.corners[held.start], dir, v) : kNaN;
      }
      const int c = k - base - nc;
      return c != held.end ? along(held.corners[held.end], dir, v) - along(held.corners[c], dir, v) : kNaN;
    }
    default: return kNaN;
  }
}

}  // namespace stoneskip

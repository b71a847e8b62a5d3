#include "model/stone/mass_properties.hpp"

namespace stoneskip {

namespace {

// Eberly 2002, "Subexpressions": polynomial integrals of one coordinate over a triangle.
struct Sub {
  double f1, f2, f3, g0, g1, g2;
};
Sub subexpressions(double w0, double w1, double w2) {
  Sub s;
  const double t0 = w0 + w1;
  s.f1 = t0 + w2;
  const double t1 = w0 * w0;
  const double t2 = t1 + w1 * t0;
  s.f2 = t2 + w2 * s.f1;
  s.f3 = w0 * t1 + w1 * t2 + w2 * s.f2;
  s.g0 = s.f2 + w0 * (s.f1 + w0);
  s.g1 = s.f2 + w1 * (s.f1 + w1);
  s.g2 = s.f2 + w2 * (s.f1 + w2);
  return s;
}

// Unit-density integrals: 1, x, y, z, x², y², z², xy, yz, zx over the enclosed volume.
MassProperties unit_density(const Mesh& mesh) {
  double in[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  for (const auto& t : mesh.triangles) {
    const Vec3& p0 = mesh.vertices[t[0]];
    const Vec3& p1 = mesh.vertices[t[1]];
    const Vec3& p2 = mesh.vertices[t[2]];
    const double a1 = p1.x() - p0.x(), b1 = p1.y() - p0.y(), c1 = p1.z() - p0.z();
    const double a2 = p2.x() - p0.x(), b2 = p2.y() - p0.y(), c2 = p2.z() - p0.z();
    const double d0 = b1 * c2 - b2 * c1, d1 = a2 * c1 - a1 * c2, d2 = a1 * b2 - a2 * b1;
    const Sub x = subexpressions(p0.x(), p1.x(), p2.x());
    const Sub y = subexpressions(p0.y(), p1.y(), p2.y());
    const Sub z = subexpressions(p0.z(), p1.z(), p2.z());
    in[0] += d0 * x.f1;
    in[1] += d0 * x.f2;
    in[2] += d1 * y.f2;
    in[3] += d2 * z.f2;
    in[4] += d0 * x.f3;
    in[5] += d1 * y.f3;
    in[6] += d2 * z.f3;
    in[7] += d0 * (p0.y() * x.g0 + p1.y() * x.g1 + p2.y() * x.g2);
    in[8] += d1 * (p0.z() * y.g0 + p1.z() * y.g1 + p2.z() * y.g2);
    in[9] += d2 * (p0.x() * z.g0 + p1.x() * z.g1 + p2.x() * z.g2);
  }
  in[0] /= 6.0;
  for (int i = 1; i <= 3; ++i) in[i] /= 24.0;
  for (int i = 4; i <= 6; ++i) in[i] /= 60.0;
  for (int i = 7; i <= 9; ++i) in[i] /= 120.0;

  MassProperties mp;
  mp.volume_m3 = in[0];
  mp.mass_kg = in[0];
  mp.density_kg_m3 = 1.0;
  const Vec3 c(in[1] / in[0], in[2] / in[0], in[3] / in[0]);
  mp.center_of_mass_m = c;
  // Inertia about the origin, then moved to the centre of mass (parallel-axis theorem).
  Mat3 I;
  I(0, 0) = in[5] + in[6] - in[0] * (c.y() * c.y() + c.z() * c.z());
  I(1, 1) = in[4] + in[6] - in[0] * (c.z() * c.z() + c.x() * c.x());
  I(2, 2) = in[4] + in[5] - in[0] * (c.x() * c.x() + c.y() * c.y());
  I(0, 1) = I(1, 0) = -(in[7] - in[0] * c.x() * c.y());
  I(1, 2) = I(2, 1) = -(in[8] - in[0] * c.y() * c.z());
  I(0, 2) = I(2, 0) = -(in[9] - in[0] * c.z() * c.x());
  mp.inertia_kg_m2 = I;
  return mp;
}

}  // namespace

MassProperties mass_properties_from_density(const Mesh& mesh, double density_kg_m3) {
  MassProperties mp = unit_density(mesh);
  mp.density_kg_m3 = density_kg_m3;
  mp.mass_kg = mp.volume_m3 * density_kg_m3;
  mp.inertia_kg_m2 *= density_kg_m3;
  return mp;
}

MassProperties mass_properties_from_mass(const Mesh& mesh, double mass_kg) {
  const MassProperties unit = unit_density(mesh);
  return mass_properties_from_density(mesh, mass_kg / unit.volume_m3);
}

}  // namespace stoneskip

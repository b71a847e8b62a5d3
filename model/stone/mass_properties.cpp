#include "model/stone/mass_properties.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>

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

// unit_density about a point near the mesh: the parallel-axis step cancels m |c|² against the
// second moments about the origin, so a mesh written far from its origin (a scan in world
// coordinates) would lose digits in proportion to (|c| / size)². A mesh whose vertex mean lies
// farther from the origin than a tenth of its size is integrated about that mean instead; meshes
// built around the origin (make_prism, make_lens) are integrated exactly as before.
MassProperties unit_density_near(const Mesh& mesh) {
  Vec3 mean = Vec3::Zero();
  for (const auto& v : mesh.vertices) mean += v;
  if (!mesh.vertices.empty()) mean /= static_cast<double>(mesh.vertices.size());
  double size = 0;
  for (const auto& v : mesh.vertices) size = std::max(size, (v - mean).norm());
  if (!(mean.norm() > 0.1 * size)) return unit_density(mesh);
  Mesh shifted = mesh;
  for (auto& v : shifted.vertices) v -= mean;
  MassProperties mp = unit_density(shifted);
  mp.center_of_mass_m += mean;
  return mp;
}

}  // namespace

MassProperties mass_properties_from_density(const Mesh& mesh, double density_kg_m3) {
  MassProperties mp = unit_density_near(mesh);
  mp.density_kg_m3 = density_kg_m3;
  mp.mass_kg = mp.volume_m3 * density_kg_m3;
  mp.inertia_kg_m2 *= density_kg_m3;
  return mp;
}

MassProperties mass_properties_from_mass(const Mesh& mesh, double mass_kg) {
  const MassProperties unit = unit_density_near(mesh);
  return mass_properties_from_density(mesh, mass_kg / unit.volume_m3);
}

namespace {

constexpr double kTie = 1e-9;  // a relative quantity this small counts as zero

// ±a, positive along the mesh axis (in `order` of preference among equals) it is most parallel to.
Vec3 along_largest_component(const Vec3& a, std::array<int, 3> order) {
  int best = order[0];
  for (int k : order)
    if (std::abs(a[k]) > std::abs(a[best]) * (1 + kTie)) best = k;
  return a[best] >= 0 ? a : Vec3(-a);
}

// The first mesh axis (in `order`) projected onto the plane normal to z, normalised.
Vec3 projected_axis(const Vec3& z, std::array<int, 3> order) {
  for (int k : order) {
    const Vec3 p = Vec3::Unit(k) - z[k] * z;
    if (p.norm() > 1e-6) return p.normalized();
  }
  return Vec3::UnitX();  // unreachable for a unit z
}

// ±x such that the surface's third moment about the centre of mass along it is positive.
Vec3 skew_positive(const Mesh& mesh, const Vec3& center, const Vec3& x) {
  double m3 = 0, scale = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    const double s = ((a + b + c) / 3.0 - center).dot(x);
    m3 += area * s * s * s;
    scale += area * std::abs(s * s * s);
  }
  if (std::abs(m3) <= kTie * scale) return along_largest_component(x, {0, 1, 2});
  return m3 > 0 ? x : Vec3(-x);
}

}  // namespace

Mat3 principal_frame(const Mesh& mesh, const MassProperties& mp) {
  constexpr double kIdentitySnap = 1e-12;  // round-off of the eigenvectors of a diagonal tensor
  const Mat3& I = mp.inertia_kg_m2;
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(0.5 * (I + I.transpose()));
  const Eigen::Vector3d lambda = eig.eigenvalues();  // ascending
  const Mat3 e = eig.eigenvectors();
  const double tol = kTie * std::max(std::abs(lambda[2]), 1e-300);
  const bool low_equal = lambda[1] - lambda[0] <= tol, high_equal = lambda[2] - lambda[1] <= tol;
  if (low_equal && high_equal) return Mat3::Identity();
  Vec3 z, x;
  if (!high_equal) {
    z = along_largest_component(e.col(2), {2, 1, 0});
    x = low_equal ? projected_axis(z, {0, 1, 2}) : skew_positive(mesh, mp.center_of_mass_m, e.col(0));
  } else {
    x = skew_positive(mesh, mp.center_of_mass_m, e.col(0));
    z = projected_axis(x, {2, 1, 0});
  }
  x = (x - x.dot(z) * z).normalized();
  Mat3 P;
  P.col(0) = x;
  P.col(1) = z.cross(x);
  P.col(2) = z;
  if ((P - Mat3::Identity()).cwiseAbs().maxCoeff() <= kIdentitySnap) return Mat3::Identity();
  return P;
}

}  // namespace stoneskip

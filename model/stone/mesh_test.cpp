// Mesh construction, closure checks and mass properties against closed forms (model/README.md §1.1–1.2).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "model/stone/mass_properties.hpp"
#include "model/stone/mesh.hpp"

using namespace stoneskip;

namespace {
// Mass properties are sums of O(N) terms of size O(1) in units of the result: a few hundred ulps.
constexpr double kRoundoff = 1e-12;
constexpr double kPi = std::numbers::pi;
}  // namespace

BOOST_AUTO_TEST_SUITE(stone_mesh)

BOOST_AUTO_TEST_CASE(prism_and_lens_have_the_papers_44_triangles) {
  // Oracle: model/README.md §1.1 counts, 4N for the prism and 2N for the lens.
  BOOST_TEST(make_prism(0.03, 0.008, 11).triangles.size() == 44u);
  BOOST_TEST(make_lens(0.03, 0.008, 22).triangles.size() == 44u);
  BOOST_TEST(make_prism(0.03, 0.008, 11).vertices.size() == 24u);
}

BOOST_AUTO_TEST_CASE(prism_volume_is_exact) {
  // Oracle: regular N-gon prism volume (N/2) R² sin(2π/N) h (model/README.md §1.2).
  for (int n : {3, 5, 11, 64}) {
    const double R = 0.031, h = 0.0073;
    const MassProperties mp = mass_properties_from_density(make_prism(R, h, n), 1.0);
    const double exact = 0.5 * n * R * R * std::sin(2 * kPi / n) * h;
    BOOST_TEST(std::abs(mp.volume_m3 - exact) <= kRoundoff * exact, "N=" << n);
  }
}

BOOST_AUTO_TEST_CASE(lens_volume_is_two_pyramids) {
  // Oracle: the lens is two N-gon pyramids of height h/2: V = 2 · (1/3) · A_polygon · h/2.
  const double R = 0.02, h = 0.01;
  const int n = 22;
  const double area = 0.5 * n * R * R * std::sin(2 * kPi / n);
  const MassProperties mp = mass_properties_from_density(make_lens(R, h, n), 1.0);
  BOOST_TEST(std::abs(mp.volume_m3 - area * h / 3.0) <= kRoundoff * mp.volume_m3);
}

BOOST_AUTO_TEST_CASE(prism_inertia_matches_the_polygon_polar_moment_exactly) {
  // Oracle: a regular N-gon of circumradius R has polar moment m R² (1 + 2 cos²(π/N)) / 6; by
  // symmetry its in-plane moments are half of it, so I_xx = I_yy = m R²(1+2cos²(π/N))/12 + m h²/12.
  for (int n : {3, 4, 7, 11, 50}) {
    const double R = 0.03, h = 0.008, rho = 2500;
    const MassProperties mp = mass_properties_from_density(make_prism(R, h, n), rho);
    const double m = mp.mass_kg;
    const double polar = m * R * R * (1 + 2 * std::pow(std::cos(kPi / n), 2)) / 6.0;
    BOOST_TEST(std::abs(mp.inertia_kg_m2(2, 2) - polar) <= kRoundoff * polar, "N=" << n);
    const double ixx = polar / 2 + m * h * h / 12.0;
    BOOST_TEST(std::abs(mp.inertia_kg_m2(0, 0) - ixx) <= kRoundoff * ixx, "N=" << n);
    BOOST_TEST(std::abs(mp.inertia_kg_m2(1, 1) - ixx) <= kRoundoff * ixx, "N=" << n);
    BOOST_TEST(std::abs(mp.inertia_kg_m2(0, 1)) <= kRoundoff * polar);
    BOOST_TEST(mp.center_of_mass_m.norm() <= kRoundoff * R);
  }
}

BOOST_AUTO_TEST_CASE(prism_inertia_tends_to_the_disk_as_n_grows) {
  // Oracle: the solid disk, I_zz = m R²/2, I_xx = m R²/4 + m h²/12; the polygon's relative error
  // is 1 − (1+2cos²(π/N))/3 = (2/3) sin²(π/N) ≈ (2/3)(π/N)², so it must fall 4× per doubling.
  const double R = 0.025, h = 0.00275;
  double previous = 0;
  for (int n : {16, 32, 64, 128, 256}) {
    const MassProperties mp = mass_properties_from_mass(make_prism(R, h, n), 0.0146);
    const double m = mp.mass_kg;
    const double err_zz = std::abs(mp.inertia_kg_m2(2, 2) - m * R * R / 2) / (m * R * R / 2);
    const double err_xx = std::abs(mp.inertia_kg_m2(0, 0) - (m * R * R / 4 + m * h * h / 12)) / (m * R * R / 4);
    BOOST_TEST(std::abs(err_zz - (2.0 / 3.0) * std::pow(std::sin(kPi / n), 2)) <= 1e-10);
    BOOST_TEST(std::abs(err_xx - err_zz) <= 1e-10);  // in-plane moments are half the polar one
    if (previous > 0) BOOST_TEST(previous / err_zz == 4.0, boost::test_tools::tolerance(0.01));
    previous = err_zz;
    BOOST_TEST(std::abs(m - 0.0146) <= kRoundoff * m);  // a mass was given: it is kept exactly
  }
}

BOOST_AUTO_TEST_CASE(parametric_meshes_are_closed_and_outward) {
  // Oracle: closure and orientation by construction (model/README.md §1.1).
  for (const Mesh& m : {make_prism(0.03, 0.008, 11), make_lens(0.03, 0.008, 22), make_prism(1, 1, 3)}) {
    const MeshCheck c = check_mesh(m);
    BOOST_TEST(c.ok, c.problem);
    BOOST_TEST(c.signed_volume_m3 > 0);
  }
}

BOOST_AUTO_TEST_CASE(a_centre_split_rim_is_its_own_mirror_image_and_the_diagonal_split_is_not) {
  // Oracle: geometry. A triangle's water force depends on its centroid, area and normal, so a mesh
  // whose set of (centroid, area × normal) is unchanged by the mirror y → −y (normals mirror too)
  // gives a mirrored throw the mirrored forces. The prism's vertices are symmetric (θ_k and −θ_k),
  // but every diagonal cut has the same hand: its mirror image is a mesh cut the other way. The
  // centre split (6N triangles, same solid) is symmetric; the volume is the prism's either way.
  auto mirror_mismatch = [](const Mesh& m) {
    std::vector<std::pair<Vec3, Vec3>> faces;  // centroid, area-weighted normal
    for (const auto& t : m.triangles) {
      const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
      faces.emplace_back((a + b + c) / 3, 0.5 * (b - a).cross(c - a));
    }
    double worst = 0;  // the largest distance from a mirrored face to the nearest face
    for (const auto& [c, n] : faces) {
      const Vec3 mc(c.x(), -c.y(), c.z()), mn(n.x(), -n.y(), n.z());
      double best = 1e300;
      for (const auto& [d, k] : faces) best = std::min(best, (mc - d).norm() + (mn - k).norm() / 0.03);
      worst = std::max(worst, best);
    }
    return worst;
  };
  constexpr double kSame = 1e-15;  // round-off of the vertex coordinates (metres, R = 0.03)
  for (int n : {3, 11, 12}) {
    const Mesh centre = make_prism(0.03, 0.008, n, RimSplit::centre), diagonal = make_prism(0.03, 0.008, n);
    BOOST_TEST(centre.triangles.size() == 6u * n);
    BOOST_TEST(check_mesh(centre).ok, check_mesh(centre).problem);
    BOOST_TEST(mirror_mismatch(centre) <= kSame, "N=" << n);
    BOOST_TEST(mirror_mismatch(diagonal) > 1e-3, "N=" << n);  // a rim triangle's centroid moves by ~h/3
    const double v = mass_properties_from_density(centre, 1.0).volume_m3, w = mass_properties_from_density(diagonal, 1.0).volume_m3;
    BOOST_TEST(std::abs(v - w) <= kRoundoff * w);
  }
  RimSplit s;
  BOOST_TEST(parse_rim_split("centre", s));
  BOOST_TEST((s == RimSplit::centre));
  BOOST_TEST(!parse_rim_split("center", s));
}

BOOST_AUTO_TEST_CASE(a_mesh_far_from_the_origin_is_judged_by_its_own_size) {
  // Oracle: translation invariance. A closed outward box of 6 × 4 × 1 cm is the same solid at the
  // origin and 1.2e5, 1.8e5 or 9e5 m away (coordinates exact to 1e-11 m there): accepted each time,
  // with the box's volume to the round-off of those coordinates. It had been called inward at
  // 1.2e5 m and degenerate at 1.8e5 m. A triangle that names one vertex twice is named as such.
  auto box = [](double off) {
    Mesh m;
    for (int i = 0; i < 8; ++i)
      m.vertices.push_back(Vec3(off + (i & 1 ? 0.06 : 0.0), off + (i & 2 ? 0.04 : 0.0), off + (i & 4 ? 0.01 : 0.0)));
    // Outward triangles of the six faces (x−, x+, y−, y+, z−, z+).
    m.triangles = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                   {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
    return m;
  };
  for (double off : {0.0, 1.2e5, 1.8e5, 9e5}) {
    const MeshCheck c = check_mesh(box(off));
    BOOST_TEST(c.ok, "offset " << off << ": " << c.problem);
    BOOST_TEST(std::abs(c.signed_volume_m3 - 2.4e-5) <= 1e-9, "offset " << off << ": " << c.signed_volume_m3);
  }
  Mesh bad = box(0);
  bad.triangles.push_back({0, 0, 1});
  BOOST_TEST(check_mesh(bad).problem.find("names one vertex twice") != std::string::npos, check_mesh(bad).problem);
}

BOOST_AUTO_TEST_CASE(open_flipped_and_inward_meshes_are_rejected) {
  // Oracle: edge counting; each defect planted by hand.
  Mesh open = make_prism(0.03, 0.008, 11);
  open.triangles.pop_back();
  BOOST_TEST(!check_mesh(open).ok);
  BOOST_TEST(check_mesh(open).boundary_edges == 3);

  BOOST_TEST(check_mesh(open).problem == "the mesh is open: 3 edges belong to one triangle only", check_mesh(open).problem);

  // The same closed prism as a triangle soup (each face with its own copies of its corners): open
  // by its edges, and the line says why and what mends it. 44 faces × 3 corners over 24 positions
  // (a prism of 11 sides: 22 rim corners and the two face centres) repeat 132 − 24 = 108 times.
  const Mesh prism = make_prism(0.03, 0.008, 11);
  Mesh soup;
  for (const auto& t : prism.triangles) {
    const int k = static_cast<int>(soup.vertices.size());
    for (int e = 0; e < 3; ++e) soup.vertices.push_back(prism.vertices[t[e]]);
    soup.triangles.push_back({k, k + 1, k + 2});
  }
  const MeshCheck sc = check_mesh(soup);
  BOOST_TEST(!sc.ok);
  BOOST_TEST(sc.problem.find("(" + std::to_string(3 * prism.triangles.size() - prism.vertices.size()) +
                             " vertices repeat another's position: merge duplicate vertices") != std::string::npos,
             sc.problem);

  // Merged, the soup is the prism again: its 24 positions, its triangles' corners at the same
  // points (exactly: nothing moves) and a closed, outward mesh of the same volume.
  Mesh welded = soup;
  std::vector<long> lines(soup.vertices.size());
  for (std::size_t i = 0; i < lines.size(); ++i) lines[i] = static_cast<long>(i) + 1;
  BOOST_TEST(merge_repeated_vertices(welded, &lines) == static_cast<int>(3 * prism.triangles.size() - prism.vertices.size()));
  BOOST_TEST(welded.vertices.size() == prism.vertices.size());
  BOOST_TEST(lines.size() == welded.vertices.size());
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
    for (int e = 0; e < 3; ++e) BOOST_TEST(welded.vertices[welded.triangles[t][e]] == soup.vertices[soup.triangles[t][e]]);
  for (std::size_t v = 0; v < welded.vertices.size(); ++v)  // each kept vertex keeps its own line
    BOOST_TEST(soup.vertices[lines[v] - 1] == welded.vertices[v]);
  const MeshCheck wc = check_mesh(welded);
  BOOST_TEST(wc.ok, wc.problem);
  BOOST_TEST(wc.signed_volume_m3 == check_mesh(prism).signed_volume_m3, boost::test_tools::tolerance(1e-12));
  // A mesh without repeats is left as it is, numbering included.
  Mesh same = prism;
  BOOST_TEST(merge_repeated_vertices(same) == 0);
  BOOST_TEST(same.triangles == prism.triangles);

  Mesh flipped = make_prism(0.03, 0.008, 11);
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  BOOST_TEST(!check_mesh(flipped).ok);
  BOOST_TEST(check_mesh(flipped).misoriented_edges > 0);

  Mesh inward = make_lens(0.03, 0.008, 22);
  BOOST_TEST(check_mesh(inward).at_fault == -1);  // closed and outward: nothing at fault
  for (auto& t : inward.triangles) std::swap(t[1], t[2]);
  const MeshCheck c = check_mesh(inward);
  BOOST_TEST(!c.ok);
  BOOST_TEST(c.signed_volume_m3 < 0);
  BOOST_TEST(c.problem.find("inward") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_triangle_at_fault_is_named) {
  // Oracle: each defect planted by hand at a known triangle of the 44-triangle prism, so that a
  // reader of a large OBJ file is sent to the face to mend (tools/scene/stone_case.cpp names its line).
  const Mesh prism = make_prism(0.03, 0.008, 11);
  for (int k : {0, 17, 43}) {
    // A face flipped alone: all three of its edges are traversed twice one way, each neighbour's one.
    Mesh flipped = prism;
    std::swap(flipped.triangles[k][1], flipped.triangles[k][2]);
    BOOST_TEST(check_mesh(flipped).at_fault == k);

    // A face removed: the first triangle at fault owns one of the hole's edges, so it shares two
    // vertices with the face removed.
    Mesh open = prism;
    open.triangles.erase(open.triangles.begin() + k);
    const MeshCheck c = check_mesh(open);
    BOOST_REQUIRE(c.at_fault >= 0);
    int shared = 0;
    for (int v : open.triangles[c.at_fault]) shared += std::count(prism.triangles[k].begin(), prism.triangles[k].end(), v);
    BOOST_TEST(shared == 2, "face " << k << ": triangle " << c.at_fault);
  }
  Mesh repeated = prism;
  repeated.triangles.push_back({3, 3, 5});
  BOOST_TEST(check_mesh(repeated).at_fault == 44);
  // A third triangle on an edge: the first user of that edge (triangle 0's edge from the top centre).
  Mesh fin = prism;
  const int apex = static_cast<int>(fin.vertices.size());
  fin.vertices.push_back(Vec3(0, 0, 0.05));
  fin.triangles.push_back({0, prism.triangles[0][1], apex});
  fin.triangles.push_back({prism.triangles[0][1], 0, apex});
  const MeshCheck f = check_mesh(fin);
  BOOST_TEST(f.problem.find("shared by more than two") != std::string::npos, f.problem);
  BOOST_TEST(f.at_fault == 0);
}

BOOST_AUTO_TEST_CASE(a_vertex_no_triangle_names_is_refused_and_named) {
  // Oracle: a vertex planted by hand that no face names. Everything that walks the vertex list (the
  // contact's events, the bounding and air disk radii) would take it for a point of the stone: one
  // 1.5 cm below the tumbling hard case's stone started its first contact 0.11 ms early. The
  // generated stones name every vertex they make.
  const Mesh prism = make_prism(0.03, 0.008, 11);
  BOOST_TEST(check_mesh(prism).loose_vertices == 0);
  BOOST_TEST(check_mesh(make_prism(0.03, 0.008, 11, RimSplit::centre)).loose_vertices == 0);
  BOOST_TEST(check_mesh(make_lens(0.03, 0.008, 22)).loose_vertices == 0);
  BOOST_TEST(check_mesh(make_icosphere(0.02, 2)).loose_vertices == 0);
  Mesh loose = prism;
  const int first = static_cast<int>(loose.vertices.size());
  loose.vertices.push_back(Vec3(0, 0, -0.015));
  loose.vertices.push_back(Vec3(0, 0, 0));  // inside the stone: still no point of its surface
  const MeshCheck c = check_mesh(loose);
  BOOST_TEST(!c.ok);
  BOOST_TEST(c.loose_vertices == 2);
  BOOST_TEST(c.vertex_at_fault == first);
  BOOST_TEST(c.at_fault == -1);
  BOOST_TEST(c.problem.find("2 vertices belong to no triangle") == 0u, c.problem);
  // An open mesh's hole is named first: the loose vertex is the lesser fault.
  loose.triangles.pop_back();
  BOOST_TEST(check_mesh(loose).problem.find("the mesh is open") == 0u, check_mesh(loose).problem);
}

BOOST_AUTO_TEST_CASE(icosphere_volume_and_inertia_lie_between_its_inner_and_outer_balls) {
  // Oracle: every vertex lies on the sphere and the solid is convex, so it contains the ball of
  // radius r_in (its smallest face-plane distance) and lies inside the ball of radius R: its volume
  // and polar moment lie between the balls' (4/3)πr³ and (8/15)πρr⁵ (the discretisation's known
  // error, O(h²)), up to round-off. Icosahedral symmetry makes the inertia isotropic exactly.
  const double R = 0.02, rho = 2650;
  double previous_deficit = 1;
  for (int n : {0, 1, 2, 3}) {
    const Mesh m = make_icosphere(R, n);
    BOOST_TEST(m.triangles.size() == 20u * (1u << (2 * n)));
    const MeshCheck c = check_mesh(m);
    BOOST_TEST(c.ok, c.problem);
    double r_in = R;
    for (const auto& t : m.triangles) {
      const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &d = m.vertices[t[2]];
      r_in = std::min(r_in, std::abs((b - a).cross(d - a).normalized().dot(a)));
    }
    const MassProperties mp = mass_properties_from_density(m, rho);
    const double v_in = 4.0 / 3.0 * kPi * std::pow(r_in, 3), v_out = 4.0 / 3.0 * kPi * std::pow(R, 3);
    BOOST_TEST(mp.volume_m3 >= v_in * (1 - kRoundoff), "n=" << n);
    BOOST_TEST(mp.volume_m3 <= v_out * (1 + kRoundoff), "n=" << n);
    const double i_in = 8.0 / 15.0 * kPi * rho * std::pow(r_in, 5), i_out = 8.0 / 15.0 * kPi * rho * std::pow(R, 5);
    for (int k = 0; k < 3; ++k) {
      BOOST_TEST(mp.inertia_kg_m2(k, k) >= i_in * (1 - kRoundoff), "n=" << n);
      BOOST_TEST(mp.inertia_kg_m2(k, k) <= i_out * (1 + kRoundoff), "n=" << n);
      BOOST_TEST(std::abs(mp.inertia_kg_m2(k, k) - mp.inertia_kg_m2(0, 0)) <= kRoundoff * i_out, "n=" << n);
    }
    BOOST_TEST(mp.center_of_mass_m.norm() <= kRoundoff * R);
    // Each subdivision cuts the volume deficit by about 4 (h halves, the error is O(h²)): at least 3.
    const double deficit = 1 - mp.volume_m3 / v_out;
    if (n > 0) BOOST_TEST(deficit < previous_deficit / 3, "n=" << n);
    previous_deficit = deficit;
  }
}

BOOST_AUTO_TEST_SUITE_END()

#pragma once
// A stone is a closed, outward-oriented triangle mesh (model/README.md §1.1). Two parametric families:
//   prism: regular N-gon prism, 4N triangles (N = 11 gives Lee & Baek's 44);
//   lens:  biconvex stone, one rim ring and two apexes, 2N triangles (N = 22 gives 44).
// And a sphere (Johnson & Reid's ricochet of spheres, model/README.md §3): an icosphere, 20·4^n triangles.
// A mesh may also come from a Wavefront OBJ file (tools/io/obj_reader.hpp); check_mesh() says
// whether it is closed and outward-oriented.
#include <Eigen/Dense>  // Core + Geometry (cross products, quaternions)
#include <array>
#include <string>
#include <vector>

namespace stoneskip {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside
};

// How a prism's rectangular rim faces are cut into triangles.
//   diagonal: two triangles per face, each cut along the diagonal from its bottom corner at θ_k to
//             its top corner at θ_(k+1) (spec §1.1: 4N triangles, the paper's 44 at N = 11). Every
//             cut has the same hand, so the mesh is not its own mirror image: a throw and its mirror
//             (spin reversed) do not mirror each other, as the triangles' forces differ (model/README.md
//             §1.1 gives the size of the effect).
//   centre:   four triangles per face, fanned from the face's centre (6N triangles): the mesh is its
//             own mirror image in every plane through the axis and a vertex or a face's middle.
enum class RimSplit { diagonal, centre };
const char* to_string(RimSplit s);
bool parse_rim_split(const std::string& s, RimSplit& out);

// Flat cylinder approximated by a regular N-gon prism of circumradius R and thickness h (§1.1).
Mesh make_prism(double radius_m, double thickness_m, int segments, RimSplit split = RimSplit::diagonal);
// Biconvex lens: rim ring of N vertices at z = 0, apexes at z = ±h/2 (§1.1).
Mesh make_lens(double radius_m, double thickness_m, int segments);
// Sphere of radius R: the regular icosahedron inscribed in it, each triangle split `subdivisions`
// times into four with the new vertices pushed out onto the sphere (20·4^n triangles, every vertex
// on the sphere: the solid lies between the ball of radius R and that of its smallest face distance).
Mesh make_icosphere(double radius_m, int subdivisions);

struct MeshCheck {
  bool ok = false;                 // closed, consistently and outward oriented, non-degenerate
  int boundary_edges = 0;          // edges used by one triangle (holes)
  int nonmanifold_edges = 0;       // edges used by more than two triangles
  int misoriented_edges = 0;       // edges traversed twice in the same direction
  int degenerate_triangles = 0;    // zero-area triangles
  int bad_indices = 0;             // triangle indices outside the vertex list
  int repeated_vertex_triangles = 0;  // triangles naming one vertex twice ("f 1 1 2")
  int loose_vertices = 0;          // vertices no triangle names (the stone's events watch every vertex)
  double signed_volume_m3 = 0;     // > 0 for an outward-oriented closed mesh
  std::string problem;             // first problem found, in words; empty when ok
  int at_fault = -1;               // for `problem`, a triangle (0-based) at fault: the first among
                                   // those the problem counts (for edges traversed twice one way,
                                   // the triangle with most of them: a flipped face has all three);
                                   // -1 where no one triangle is (an inward mesh, loose vertices)
  int vertex_at_fault = -1;        // for loose vertices, the first (0-based); -1 otherwise
};

MeshCheck check_mesh(const Mesh& mesh);

// Merges vertices at exactly the same position (every coordinate equal) into the first of them and
// renumbers the triangles: a mesh exported unwelded (a triangle soup, as from STL, each face with
// its own copies of its corners) becomes the closed mesh it describes. Nothing moves: the solid and
// its mass properties are unchanged. vertex_lines (one entry per vertex, or null) is kept in step.
// Returns how many vertices were merged away.
int merge_repeated_vertices(Mesh& mesh, std::vector<long>* vertex_lines = nullptr);

}  // namespace stoneskip

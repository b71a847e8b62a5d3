#include "tools/scene/obj_reader.hpp"

#include <cmath>
#include <sstream>

#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip {

Mesh parse_obj(const std::string& text, const std::string& name, std::vector<long>* triangle_lines,
               std::vector<long>* vertex_lines) {
  Mesh m;
  if (triangle_lines) triangle_lines->clear();
  if (vertex_lines) vertex_lines->clear();
  std::istringstream in(text);
  std::string line;
  long line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream ls(line);
    std::string tag;
    if (!(ls >> tag) || tag[0] == '#') continue;
    if (tag == "v") {
      double x, y, z;
      if (!(ls >> x >> y >> z) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
        throw_input_error(name, line_no, "", "a vertex needs three finite numbers");
      if (std::abs(x) > kMaxObjCoordinate_m || std::abs(y) > kMaxObjCoordinate_m || std::abs(z) > kMaxObjCoordinate_m)
        throw_input_error(name, line_no, "", "a vertex coordinate beyond ±1e6 m");
      m.vertices.emplace_back(x, y, z);
      if (vertex_lines) vertex_lines->push_back(line_no);
    } else if (tag == "f") {
      std::vector<int> idx;
      std::string tok;
      while (ls >> tok) {
        const std::string head = tok.substr(0, tok.find('/'));
        long k = 0;
        try {
          std::size_t used = 0;
          k = std::stol(head, &used);
          if (used != head.size()) throw std::invalid_argument("trailing");
        } catch (const std::exception&) {
          throw_input_error(name, line_no, "", "bad face index '" + tok + "'");
        }
        const long nv = static_cast<long>(m.vertices.size());
        const long i = k > 0 ? k - 1 : nv + k;  // OBJ: 1-based, negative = relative
        if (k == 0 || i < 0 || i >= nv)
          throw_input_error(name, line_no, "", "face index " + tok + " refers to no vertex defined so far");
        idx.push_back(static_cast<int>(i));
      }
      if (idx.size() < 3) throw_input_error(name, line_no, "", "a face needs at least three vertices");
      for (std::size_t k = 1; k + 1 < idx.size(); ++k) {
        m.triangles.push_back({idx[0], idx[k], idx[k + 1]});
        if (triangle_lines) triangle_lines->push_back(line_no);
      }
      if (m.triangles.size() > kMaxObjTriangles)
        throw_input_error(name, line_no, "", "more than " + std::to_string(kMaxObjTriangles) + " triangles (a limit)");
    }
  }
  if (m.triangles.empty()) throw_input_error(name, 0, "", "no faces found (is this a Wavefront OBJ file?)");
  return m;
}

Mesh read_obj(const std::string& path, std::vector<long>* triangle_lines, std::vector<long>* vertex_lines) {
  return parse_obj(read_text_file(path, kMaxObjBytes), path, triangle_lines, vertex_lines);
}

}  // namespace stoneskip

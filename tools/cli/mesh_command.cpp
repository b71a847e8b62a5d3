// stoneskip mesh CASE [--set key=value ...] [--json]: the stone's mesh and its mass properties.
#include <cstdio>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "tools/cli/command_registry.hpp"
#include "tools/cli/json_output.hpp"
#include "tools/scene/stone_case.hpp"

namespace stoneskip::cli {
namespace {

void add_mesh(CLI::App& app) {
  auto file = std::make_shared<std::string>();
  auto sets = std::make_shared<std::vector<std::string>>();
  auto json = std::make_shared<bool>(false);
  auto* cmd = app.add_subcommand("mesh", "Print a case's stone mesh (body frame) and its mass properties");
  cmd->add_option("CASE", *file, "Stone case file")->required();
  cmd->add_option("--set", *sets, "Override a case key: section.key=value (repeatable)");
  cmd->add_flag("--json", *json, "Print one JSON object");
  cmd->callback([file, sets, json] {
    const StoneCase c = load_stone_case(*file, *sets);
    const Stone& s = c.stone;
    const MeshCheck check = check_mesh(s.body_mesh);
    const Mat3& I = s.inertia_body_kg_m2;
    if (*json) {
      nlohmann::json j;
      j["description"] = s.description;
      j["vertices"] = s.body_mesh.vertices.size();
      j["triangles"] = s.body_mesh.triangles.size();
      j["closed_and_outward"] = check.ok;
      j["volume_m3"] = s.mass.volume_m3;
      j["density_kg_m3"] = s.mass.density_kg_m3;
      j["mass_kg"] = s.mass.mass_kg;
      j["disk_radius_m"] = s.disk_radius_m;
      j["disk_area_m2"] = s.disk_area_m2;
      // The mesh itself, as the text form prints it (body frame, metres; counter-clockwise from outside).
      nlohmann::json vs = nlohmann::json::array(), ts = nlohmann::json::array();
      for (const auto& v : s.body_mesh.vertices) vs.push_back({v.x(), v.y(), v.z()});
      for (const auto& t : s.body_mesh.triangles) ts.push_back({t[0], t[1], t[2]});
      j["vertex_list_m"] = vs;
      j["triangle_list"] = ts;
      j["inertia_body_kg_m2"] = {{I(0, 0), I(0, 1), I(0, 2)}, {I(1, 0), I(1, 1), I(1, 2)}, {I(2, 0), I(2, 1), I(2, 2)}};
      std::cout << json_text(j) << std::endl;
      return;
    }
    std::printf("stone        %s\n", s.description.c_str());
    std::printf("mesh         %zu vertices, %zu triangles, %s\n", s.body_mesh.vertices.size(), s.body_mesh.triangles.size(),
                check.ok ? "closed and outward-oriented" : check.problem.c_str());
    std::printf("volume       %.6g m^3\ndensity      %.6g kg/m^3\nmass         %.6g kg\n", s.mass.volume_m3,
                s.mass.density_kg_m3, s.mass.mass_kg);
    std::printf("air disk     radius %.6g m, area %.6g m^2\n", s.disk_radius_m, s.disk_area_m2);
    std::printf("inertia about the centre of mass, body frame (kg m^2):\n");
    for (int i = 0; i < 3; ++i) std::printf("  [% .6e % .6e % .6e]\n", I(i, 0), I(i, 1), I(i, 2));
    std::printf("vertices (body frame, m):\n");
    for (std::size_t k = 0; k < s.body_mesh.vertices.size(); ++k) {
      const auto& v = s.body_mesh.vertices[k];
      std::printf("  %3zu  % .6f % .6f % .6f\n", k, v.x(), v.y(), v.z());
    }
    std::printf("triangles (vertex indices, counter-clockwise from outside):\n");
    for (std::size_t k = 0; k < s.body_mesh.triangles.size(); ++k) {
      const auto& t = s.body_mesh.triangles[k];
      std::printf("  %3zu  %d %d %d\n", k, t[0], t[1], t[2]);
    }
  });
}

const bool kRegistered = register_command(add_mesh);

}  // namespace
}  // namespace stoneskip::cli

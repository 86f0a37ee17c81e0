// `vdc mesh mug --out mug.ply`: writes the built-in object.
// `vdc mesh check FILE`: loads any supported mesh and reports whether it can be trained on.
// `vdc mesh scale FILE --factor F --out OUT`: writes the mesh scaled, e.g. a BOP model (mm) in
// metres with --factor 0.001, so that `vdc train` takes it.
#include <iostream>
#include <memory>

#include "commands.h"
#include "view_direction_classification/bop/bop_units.h"
#include "view_direction_classification/geometry/mesh_check.h"
#include "view_direction_classification/geometry/mesh_io.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc::tools {

namespace {

void printMeshSummary(const TriangleMesh& mesh, const MeshCheck& check) {
  const Eigen::Vector3f size = mesh.bounds().sizes();
  std::cout << mesh.vertices.size() << " vertices, " << mesh.triangles.size() << " triangles, "
            << "area " << mesh.area() * 1e4 << " cm^2, size " << size.x() * 100 << " x "
            << size.y() * 100 << " x " << size.z() * 100 << " cm, "
            << (check.watertight ? "watertight" : "not watertight") << "\n";
}

}  // namespace

void addMeshCommand(CLI::App& app) {
  auto* mesh = app.add_subcommand("mesh", "write the built-in object, or check a mesh file");
  mesh->require_subcommand(1);

  auto* mug = mesh->add_subcommand("mug", "the built-in mug (doc/method.md section 1), in metres");
  auto out = std::make_shared<std::string>();
  mug->add_option("--out", *out, "PLY file to write")->required();
  mug->callback([out] {
    const TriangleMesh mug_mesh = makeMug();
    saveMeshPly(mug_mesh, *out);
    std::cout << "wrote " << *out << ": ";
    printMeshSummary(mug_mesh, checkMesh(mug_mesh));
  });

  auto* check = mesh->add_subcommand("check", "load a PLY/STL/OBJ/OFF mesh and check it");
  auto path = std::make_shared<std::string>();
  check->add_option("file", *path, "mesh file")->required();
  check->callback([path] {
    const TriangleMesh loaded = loadMesh(*path);
    const MeshCheck report = checkMesh(loaded);
    std::cout << *path << ": ";
    printMeshSummary(loaded, report);
    for (const auto& warning : validateObjectMesh(loaded, *path)) {
      std::cerr << "warning: " << warning << "\n";
    }
  });

  auto* scale = mesh->add_subcommand(
      "scale", "write a mesh scaled by a factor (a BOP model in mm to metres: --factor 0.001)");
  struct ScaleOptions {
    std::string path, out;
    double factor = 0.001;
  };
  auto scaling = std::make_shared<ScaleOptions>();
  scale->add_option("file", scaling->path, "mesh file")->required();
  scale->add_option("--factor", scaling->factor, "every coordinate is multiplied by it")
      ->capture_default_str()
      ->check(CLI::Range(1e-6, 1e6));
  scale->add_option("--out", scaling->out, "PLY file to write")->required();
  scale->callback([scaling] {
    const TriangleMesh scaled = scaledMesh(loadMesh(scaling->path), scaling->factor);
    saveMeshPly(scaled, scaling->out);
    std::cout << "wrote " << scaling->out << ": ";
    printMeshSummary(scaled, checkMesh(scaled));
  });
}

}  // namespace vdc::tools

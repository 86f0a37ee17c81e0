// `vdc write-bop --model OBJ_ID=MESH ... --out DIR`: seeded cluttered table scenes rendered and
// written as a BOP dataset (bop_rendering.h), for `vdc evaluate-bop` and for tests without a
// download. Meshes in metres as everywhere in vdc; the dataset's models are written in mm.
#include <pcl/console/print.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bop_options.h"
#include "bop_rendering.h"
#include "commands.h"
#include "scene_evaluation_options.h"
#include "view_direction_classification/geometry/mesh_io.h"

namespace vdc::tools {
namespace {

struct WriteBopOptions {
  std::vector<std::string> models;
  std::vector<std::string> distractors;
  std::string out_dir;
  bool no_noise = false;
  BopRenderingSettings settings;
};

void runWriteBop(WriteBopOptions options) {
  const auto start = std::chrono::steady_clock::now();
  std::map<int, TriangleMesh> meshes;
  for (const auto& [obj_id, path] : parseObjectPaths(options.models, "--model")) {
    meshes[obj_id] = loadMesh(path);
  }
  options.settings.noise = !options.no_noise;
  const int images = writeRenderedBopDataset(
      options.out_dir, meshes, loadDistractorMeshes(options.distractors), options.settings);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("wrote %d scenes, %d images, %zu models to %s (%.0f s)\n", options.settings.scenes,
              images, meshes.size(), options.out_dir.c_str(), seconds);
}

}  // namespace

void addWriteBopCommand(CLI::App& app) {
  auto options = std::make_shared<WriteBopOptions>();
  BopRenderingSettings& s = options->settings;
  auto* command = app.add_subcommand(
      "write-bop",
      "render seeded cluttered table scenes and write them as a BOP dataset (mm models, "
      "models_info.json, scene_camera.json with camera poses, scene_gt.json, 16-bit depth PNGs, "
      "test_targets_bop19.json)");
  command
      ->add_option("--model", options->models,
                   "a known object as OBJ_ID=MESH (metres; repeat), placed in every scene")
      ->required();
  command->add_option("--distractor", options->distractors,
                      "an unknown object: box:X,Y,Z, cylinder:R,H or carton:X,Y,Z,GABLE[,FIN] "
                      "[m], or a mesh file (repeat; default: three boxes and two cylinders)");
  command->add_option("--out", options->out_dir, "the dataset's folder")->required();
  command->add_option("--scenes", s.scenes, "number of scenes")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  command->add_option("--views", s.generation.views, "images per scene, on the camera arc")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  command->add_option("--seed", s.seed, "scene s uses seed + s")->capture_default_str();
  command->add_option("--known", s.generation.known_objects, "known objects per scene")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  command->add_option("--distractors", s.generation.distractors, "distractors per scene")
      ->capture_default_str()
      ->check(CLI::Range(0, 100));
  command->add_flag("--no-noise", options->no_noise, "render without depth noise");
  command->callback([options] {
    // Scene generation's placement logs nothing, but PCL's readers might: keep the terminal short.
    pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
    runWriteBop(*options);
  });
}

}  // namespace vdc::tools

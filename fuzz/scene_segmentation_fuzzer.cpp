// libFuzzer target: a whole scene's cloud -> vdc::segmentScene, which every frame of the
// orientation_estimator with a model library goes through. Organised (up to 64 x 48) or
// unorganised clouds of arbitrary coordinates (NaN, infinities, huge, repeated, collinear),
// with and without the split of touching objects and with depth-dependent tolerances on or off.
// segmentScene promises never to throw or crash for a cloud's content; every candidate's
// indices must be valid, ascending and disjoint from the others'.

#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "view_direction_classification/scene/scene_segmentation.h"

namespace {

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "segmentScene broke a promise: %s\n", what);
  std::abort();
}

pcl::PointCloud<pcl::PointXYZ> fuzzedCloud(FuzzedDataProvider& data) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const bool organised = data.ConsumeBool();
  const auto width = data.ConsumeIntegralInRange<std::uint32_t>(1, 64);
  const auto height = organised ? data.ConsumeIntegralInRange<std::uint32_t>(1, 48) : 1u;
  const std::size_t count = organised ? std::size_t(width) * height
                                      : data.ConsumeIntegralInRange<std::size_t>(0, 3072);
  cloud.resize(count);
  for (auto& p : cloud.points) {
    // Mostly plausible depths (a table and things on it), sometimes anything at all.
    if (data.ConsumeBool()) {
      p.x = data.ConsumeFloatingPointInRange<float>(-1.0f, 1.0f);
      p.y = data.ConsumeFloatingPointInRange<float>(-1.0f, 1.0f);
      p.z = data.ConsumeFloatingPointInRange<float>(0.3f, 3.0f);
    } else {
      p.x = data.ConsumeFloatingPoint<float>();
      p.y = data.ConsumeFloatingPoint<float>();
      p.z = data.ConsumeFloatingPoint<float>();
    }
  }
  if (organised) {
    cloud.width = width;
    cloud.height = height;
  }
  cloud.is_dense = false;
  return cloud;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  FuzzedDataProvider data(bytes, size);
  vdc::SceneSegmentationParameters parameters;
  parameters.split_touching = data.ConsumeBool();
  if (data.ConsumeBool()) parameters.depth_tolerance_growth = 0.0;
  parameters.min_cluster_points = data.ConsumeIntegralInRange<int>(1, 60);
  parameters.min_plane_points = data.ConsumeIntegralInRange<int>(3, 2000);
  const pcl::PointCloud<pcl::PointXYZ> cloud = fuzzedCloud(data);
  const vdc::SceneSegments segments = vdc::segmentScene(cloud, parameters);
  std::vector<bool> taken(cloud.size(), false);
  for (const vdc::SceneCandidate& candidate : segments.candidates) {
    int previous = -1;
    for (int index : candidate.indices) {
      if (index < 0 || index >= static_cast<int>(cloud.size())) fail("an index outside the cloud");
      if (index <= previous) fail("indices not ascending");
      if (taken[index]) fail("a point in two candidates");
      taken[index] = true;
      previous = index;
    }
  }
  return 0;
}

// SceneEstimator::identifyParts: a known object in part of a candidate that no model explains
// whole (part_search.h). Kept apart from scene_estimator.cpp, the frame update, which calls it
// after every other identification of the frame.
#include <algorithm>
#include <string>
#include <vector>

#include "view_direction_classification/recognition/scene_estimator.h"

namespace vdc {

void SceneEstimator::identifyParts(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                   const SceneSegments& segments,
                                   std::vector<FrameCandidate>& candidates,
                                   const std::vector<bool>& unknown_alone, const SceneDepth& scene,
                                   const Eigen::Isometry3d& world_from_camera,
                                   std::optional<double> time, SceneUpdate* result) {
  std::vector<std::size_t> unknown;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    // A detector's mask is one object: it is not searched for parts.
    if (!unknown_alone[c] || candidates[c].instance >= 0 || segments.candidates[c].class_id >= 0) {
      continue;
    }
    if (result->candidates[c].instance >= 0) continue;  // a group found since, or its part
    unknown.push_back(c);
  }
  std::stable_sort(unknown.begin(), unknown.end(), [&](std::size_t a, std::size_t b) {
    return candidates[a].points.size() > candidates[b].points.size();
  });
  int searched = 0;
  for (const std::size_t c : unknown) {
    if (searched == parameters_.part_search.max_candidates) return;
    // What one simple shape explains of the whole candidate: a part must explain more, and
    // cannot where that leaves less than min_shape_gain unexplained (a box, a can).
    const double whole = shapes_->fraction(candidates[c].points, candidates[c].up, scene);
    if (whole > 1.0 - parameters_.part_search.min_shape_gain) continue;
    ++searched;
    SceneDepth candidate_scene = scene;
    candidate_scene.support_plane = candidates[c].support;
    const std::vector<CandidatePart> parts = part_search_->find(
        library_, explanations_, candidates[c].points, candidates[c].points_world,
        result->candidates[c].sides, candidate_scene, world_from_camera, time);
    for (const CandidatePart& part : parts) {
      if (identifyPart(cloud, segments, c, part, whole, candidates, scene, world_from_camera, time,
                       result)) {
        break;
      }
    }
  }
}

bool SceneEstimator::identifyPart(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                  const SceneSegments& segments, std::size_t c,
                                  const CandidatePart& part, double whole,
                                  std::vector<FrameCandidate>& candidates, const SceneDepth& scene,
                                  const Eigen::Isometry3d& world_from_camera,
                                  std::optional<double> time, SceneUpdate* result) {
  const PartSearchParameters& p = parameters_.part_search;
  std::vector<bool> in_rest(part.member.size());
  pcl::PointCloud<pcl::PointXYZ> rest;
  for (std::size_t k = 0; k < part.member.size(); ++k) {
    in_rest[k] = !part.member[k];
    if (in_rest[k]) rest.push_back(candidates[c].points[k]);
  }
  // Occam: the model on the part and one simple shape on the rest must explain more of the
  // candidate than one simple shape does of it whole.
  const double rest_fraction = shapes_->fraction(rest, candidates[c].up, scene);
  const double explained = part.points + rest_fraction * static_cast<double>(rest.size());
  const double gain = explained / static_cast<double>(candidates[c].points.size()) - whole;
  if (gain < p.min_shape_gain) return false;
  // The rest must be something too: a box or a can the object touches, or else a known object
  // (identified first, so that a model fitted into one larger thing, a cow's body into a
  // camel's, leaves the rest unexplained and is not taken).
  std::string rest_note = "the rest unknown";
  if (rest_fraction < p.min_rest_shape_fraction) {
    CandidateOutcome rest_outcome;
    if (identifySubset(cloud, segments, c, in_rest, scene, world_from_camera, time, &rest_outcome) <
        0) {
      return false;
    }
    const ObjectInstance* rest_instance = instance(rest_outcome.instance);
    rest_note = "the rest " + (rest_instance ? rest_instance->name : std::string("known"));
  }
  CandidateOutcome outcome;
  const int index =
      identifySubset(cloud, segments, c, part.member, scene, world_from_camera, time, &outcome);
  if (index < 0) return false;
  candidates[c].instance = index;
  CandidateOutcome& whole_outcome = result->candidates[c];
  whole_outcome.instance = outcome.instance;
  whole_outcome.new_instance = outcome.new_instance;
  whole_outcome.moved = outcome.moved;
  whole_outcome.probability = outcome.probability;
  whole_outcome.update = outcome.update;
  const std::string found = "found in " + std::to_string(part.points) + " of its " +
                            std::to_string(candidates[c].points.size()) + " points, " + rest_note;
  whole_outcome.note = outcome.note.empty() ? found : outcome.note + ", " + found;
  return true;
}

int SceneEstimator::identifySubset(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                   const SceneSegments& segments, std::size_t c,
                                   const std::vector<bool>& subset, const SceneDepth& scene,
                                   const Eigen::Isometry3d& world_from_camera,
                                   std::optional<double> time, CandidateOutcome* outcome) {
  SceneCandidate members = segments.candidates[c];
  members.indices.clear();
  for (std::size_t k = 0; k < subset.size(); ++k) {
    if (subset[k]) members.indices.push_back(segments.candidates[c].indices[k]);
  }
  SceneSegments whole;
  whole.planes = segments.planes;
  whole.candidates.push_back(mergedCandidate(cloud, {&members}));
  SceneUpdate merged;
  std::vector<FrameCandidate> subset_candidate =
      frameCandidates(cloud, whole, world_from_camera, &merged);
  *outcome = merged.candidates.front();
  // Not remembered when unknown: the candidate it is part of is already.
  return identify(subset_candidate.front(), scene, world_from_camera, time, outcome, false);
}

}  // namespace vdc

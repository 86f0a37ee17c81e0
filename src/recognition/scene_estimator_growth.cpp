// SceneEstimator::growNewInstances: an instance identified on one candidate alone, tried again
// with each piece beside it that nothing explains. Kept apart from scene_estimator.cpp, the frame
// update, which calls it after the groups of pieces.
#include <algorithm>
#include <string>
#include <vector>

#include "piece_groups.h"
#include "view_direction_classification/recognition/scene_estimator.h"

namespace vdc {

namespace {

// Identified alone on this frame: a new instance, or one found off its believed place.
// assigned: the candidate's instance before identification (-1: none).
bool identifiedAlone(int assigned, const CandidateOutcome& outcome) {
  return assigned < 0 && outcome.instance >= 0 && (outcome.new_instance || outcome.moved);
}

}  // namespace

void SceneEstimator::growNewInstances(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                      const SceneSegments& segments,
                                      std::vector<FrameCandidate>& candidates,
                                      const SceneDepth& scene,
                                      const Eigen::Isometry3d& world_from_camera,
                                      std::optional<double> time, SceneUpdate* result) {
  int tries = 0;
  const auto unexplained = [&](std::size_t c) {
    return candidates[c].instance < 0 && !candidates[c].ignored &&
           result->candidates[c].instance < 0 && explainingInstance(candidates[c]) < 0;
  };
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (!identifiedAlone(candidates[c].instance, result->candidates[c])) continue;
    std::vector<std::size_t> others;
    std::vector<const SceneCandidate*> parts{&segments.candidates[c]};
    for (std::size_t o = 0; o < candidates.size(); ++o) {
      if (o == c || !unexplained(o)) continue;
      others.push_back(o);
      parts.push_back(&segments.candidates[o]);
    }
    if (others.empty()) continue;
    for (const std::vector<std::size_t>& group :
         adjacentCandidateGroups(cloud, parts, parameters_.segmentation.cluster_tolerance)) {
      if (group.size() != 2 || group[0] != 0) continue;  // the instance's piece and one beside it
      const std::size_t other = others[group[1] - 1];
      if (!unexplained(other)) continue;
      const CandidateOutcome alone = result->candidates[c];
      const CandidateOutcome other_alone = result->candidates[other];
      std::vector<std::size_t> members{c, other};
      if (candidates[other].points.size() > candidates[c].points.size()) {
        std::swap(members[0], members[1]);
      }
      CandidateOutcome together;
      const ObjectInstance* kept = instance(alone.instance);
      if (!kept || tries >= parameters_.max_growth_tries) return;
      const UnionOutcome outcome =
          identifyPieces(cloud, segments, members, candidates, scene, world_from_camera, time,
                         &tries, result, &together, kept->model, parameters_.max_growth_tries);
      if (outcome != UnionOutcome::kIdentified) continue;
      kept = instance(alone.instance);  // identification may have added instances
      if (together.instance == alone.instance && kept &&
          kept->identity_probability > together.probability) {
        // The union fits the instance's model less surely than its piece alone: the piece beside
        // it is not shown to be its part, and stays free for the part search.
        result->candidates[c] = alone;
        result->candidates[other] = other_alone;
        candidates[c].instance = candidates[other].instance = -1;
        continue;
      }
      // identifyPieces reports the union on its larger piece and makes the other its part.
      CandidateOutcome& grown = result->candidates[members[0]];
      if (grown.instance == alone.instance) {
        // The same instance, refitted on both pieces, which verified at least as surely together.
        grown.new_instance = alone.new_instance;
        grown.moved = alone.moved;
        grown.note = (alone.note.empty() ? "identified" : alone.note) +
                     " with the piece beside it, which fits it at least as surely together";
      } else if (alone.new_instance) {
        // The piece belongs to another object: the instance it alone made has no other evidence.
        // dropUnlikelyInstances forgets it at the end of the frame.
        for (ObjectInstance& instance : instances_) {
          if (instance.id == alone.instance) instance.identity_probability = 0.0;
        }
      }
      CandidateOutcome& part = result->candidates[members[1]];
      part.new_instance = part.moved = false;
      break;
    }
  }
}

}  // namespace vdc

#include "bop_summary.h"

#include <cstdio>

namespace vdc::tools {
namespace {

// BOP's AR: the mean of the three average recalls (of MSSD and MSPD where VSD was not scored).
double averageRecallOf(const BopRecall& recall) {
  return recall.vsd_scored ? (recall.vsd + recall.mssd + recall.mspd) / 3.0
                           : 0.5 * (recall.mssd + recall.mspd);
}

nlohmann::json recallJson(const BopRecall& recall) {
  nlohmann::json json = {{"obj_id", recall.obj_id},       {"targets", recall.targets},
                         {"estimates", recall.estimates}, {"ar_mssd", recall.mssd},
                         {"ar_mspd", recall.mspd},        {"ar", averageRecallOf(recall)}};
  json["ar_vsd"] = recall.vsd_scored ? nlohmann::json(recall.vsd) : nlohmann::json(nullptr);
  return json;
}

void printRecall(const std::string& run, const std::string& object, const BopRecall& recall) {
  char vsd[16] = "-";
  if (recall.vsd_scored) std::snprintf(vsd, sizeof(vsd), "%.3f", recall.vsd);
  std::printf("%-8s %-8s %7d %9d %7s %7.3f %7.3f %7.3f\n", run.c_str(), object.c_str(),
              recall.targets, recall.estimates, vsd, recall.mssd, recall.mspd,
              averageRecallOf(recall));
}

}  // namespace

nlohmann::json bopSummaryJson(const std::vector<BopRun>& runs) {
  nlohmann::json summary = nlohmann::json::object();
  for (const BopRun& run : runs) {
    nlohmann::json objects = nlohmann::json::array();
    for (const BopRecall& recall : run.scores.per_object) objects.push_back(recallJson(recall));
    nlohmann::json overall = recallJson(run.scores.overall);
    overall.erase("obj_id");
    summary[run.name] = {{"objects", objects},
                         {"overall", overall},
                         {"images", run.images},
                         {"mean_image_seconds", run.mean_image_seconds}};
  }
  return summary;
}

void printBopSummary(const std::vector<BopRun>& runs) {
  std::printf("%-8s %-8s %7s %9s %7s %7s %7s %7s\n", "run", "obj_id", "targets", "estimates",
              "AR_VSD", "AR_MSSD", "AR_MSPD", "AR");
  for (const BopRun& run : runs) {
    for (const BopRecall& recall : run.scores.per_object) {
      printRecall(run.name, std::to_string(recall.obj_id), recall);
    }
  }
  for (const BopRun& run : runs) {
    printRecall(run.name, "all", run.scores.overall);
    std::printf("%-8s %d images, %.2f s per image\n", run.name.c_str(), run.images,
                run.mean_image_seconds);
  }
}

}  // namespace vdc::tools

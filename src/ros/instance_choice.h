#pragma once

#include <view_direction_classification/ObjectInstance.h>
#include <view_direction_classification/ObjectInstances.h>

#include <mutex>
#include <optional>
#include <string>

namespace vdc {

using ObjectInstanceMsg = view_direction_classification::ObjectInstance;
using ObjectInstancesMsg = view_direction_classification::ObjectInstances;

// The `instance` of a GetNextBestView or GetHeatmap request that asks for the instance whose
// belief is widest: the one a next view helps most.
inline constexpr const char* kMostUncertain = "most_uncertain";

// The instance `wanted` names among `latest` (the latest ~instances; nullptr: none received yet):
// the one of that name, or for kMostUncertain the one with the widest cone90_deg (the lowest id
// among equals, so the answer does not depend on the message's order), among the instances not
// GONE. Throws vdc::Error saying why for no message yet, a message without instances (or with only
// gone ones, for kMostUncertain), a gone instance or an unknown name (listing the known).
const ObjectInstanceMsg& chooseInstance(const ObjectInstancesMsg* latest,
                                        const std::string& wanted);

// The latest ~instances message, kept by the subscriber and read by the services (of the
// informativeness server): safe to call from several threads.
class LatestInstances {
 public:
  void keep(const ObjectInstancesMsg& message);
  // A copy of chooseInstance(latest, wanted): the next message may replace the latest meanwhile.
  ObjectInstanceMsg choose(const std::string& wanted) const;

 private:
  mutable std::mutex mutex_;
  std::optional<ObjectInstancesMsg> latest_;
};

}  // namespace vdc

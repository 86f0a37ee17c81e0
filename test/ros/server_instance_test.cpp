// The informativeness server's choice of the instance a request names, on plain messages
// (instance_choice.h), and its requests for an instance (InformativenessServerRequests): the
// instance's model, pose and belief, and a refusal with a message for every request it cannot
// answer. No ROS master: tf is a fixed lookup, the bundles are small synthetic ones.
#include <gtest/gtest.h>
#include <ros/time.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "informativeness_server_requests.h"
#include "instance_choice.h"
#include "support/axis_model_bundle.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/ros/bingham_conversions.h"

namespace vdc {
namespace {

using view_direction_classification::GetHeatmap;
using view_direction_classification::GetNextBestView;

ObjectInstanceMsg instanceMsg(std::uint32_t id, const std::string& name, const std::string& model,
                              double cone90_deg, const Eigen::Vector3d& position = {0, 0, 0}) {
  ObjectInstanceMsg instance;
  instance.id = id;
  instance.name = name;
  instance.model = model;
  instance.cone90_deg = cone90_deg;
  instance.pose.pose.position.x = position.x();
  instance.pose.pose.position.y = position.y();
  instance.pose.pose.position.z = position.z();
  instance.pose.pose.orientation.w = 1.0;
  const Eigen::Vector4d identity(1, 0, 0, 0);
  instance.belief = toBinghamMixtureMsg(BinghamMixture({1.0}, {test::sharpAround(identity)}));
  instance.belief.header.frame_id = "world";
  return instance;
}

// Three instances: mug_1 (cone 20), box_1 (cone 50, id 3) and mug_2 (cone 50, id 2, listed last).
ObjectInstancesMsg scene() {
  ObjectInstancesMsg msg;
  msg.header.frame_id = "world";
  msg.instances = {instanceMsg(1, "mug_1", "mug", 20.0, {1.0, 0.0, 0.0}),
                   instanceMsg(3, "box_1", "box", 50.0, {0.0, 1.0, 0.0}),
                   instanceMsg(2, "mug_2", "mug", 50.0, {0.0, 0.0, 1.0})};
  return msg;
}

std::string refusalOf(const ObjectInstancesMsg* latest, const std::string& wanted) {
  try {
    chooseInstance(latest, wanted);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(InstanceChoice, ANameChoosesThatInstance) {
  const ObjectInstancesMsg latest = scene();
  EXPECT_EQ(chooseInstance(&latest, "mug_1").id, 1u);
  EXPECT_EQ(chooseInstance(&latest, "box_1").id, 3u);
}

TEST(InstanceChoice, MostUncertainIsTheWidestConeAndTheLowestIdAmongEquals) {
  ObjectInstancesMsg latest = scene();
  // box_1 (id 3) comes before mug_2 (id 2) in the list, both 50 degrees: the lower id wins.
  EXPECT_EQ(chooseInstance(&latest, kMostUncertain).name, "mug_2");
  latest.instances[0].cone90_deg = 50.5;
  EXPECT_EQ(chooseInstance(&latest, kMostUncertain).name, "mug_1");
  // An unknown spread is looked at first.
  latest.instances[1].cone90_deg = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(chooseInstance(&latest, kMostUncertain).name, "box_1");
}

TEST(InstanceChoice, AnUnknownNameIsRefusedListingTheKnownOnes) {
  const ObjectInstancesMsg latest = scene();
  const std::string message = refusalOf(&latest, "cup_1");
  EXPECT_NE(message.find("Unknown instance 'cup_1'"), std::string::npos) << message;
  EXPECT_NE(message.find("mug_1, box_1, mug_2"), std::string::npos) << message;
}

// A gone instance's place was seen free: no view of it helps, by name or as the most uncertain.
TEST(InstanceChoice, AGoneInstanceIsNeitherChosenByNameNorAsTheMostUncertain) {
  ObjectInstancesMsg latest = scene();
  latest.instances[2].state = ObjectInstanceMsg::GONE;  // mug_2, which most_uncertain picks
  EXPECT_EQ(chooseInstance(&latest, kMostUncertain).name, "box_1");
  const std::string message = refusalOf(&latest, "mug_2");
  EXPECT_NE(message.find("'mug_2' is gone"), std::string::npos) << message;
  for (auto& instance : latest.instances) instance.state = ObjectInstanceMsg::GONE;
  EXPECT_NE(refusalOf(&latest, kMostUncertain).find("is gone"), std::string::npos);
}

TEST(InstanceChoice, NoMessageOrAnEmptyListIsRefused) {
  EXPECT_NE(refusalOf(nullptr, "mug_1").find("No instances received yet"), std::string::npos);
  const ObjectInstancesMsg empty;
  EXPECT_NE(refusalOf(&empty, kMostUncertain).find("has no instance"), std::string::npos);
}

TEST(InstanceChoice, TheLatestMessageReplacesTheOneBefore) {
  LatestInstances latest;
  EXPECT_THROW(latest.choose("mug_1"), Error);
  latest.keep(scene());
  EXPECT_EQ(latest.choose("mug_1").id, 1u);
  ObjectInstancesMsg next = scene();
  next.instances.erase(next.instances.begin());
  latest.keep(next);
  EXPECT_THROW(latest.choose("mug_1"), Error);
}

// The axis bundle (4 surface points) as "mug" and the single model; "box" lacks its last point,
// so a heatmap's size says which model answered.
std::shared_ptr<const ModelBundle> boxBundle() {
  auto bundle = test::makeAxisBundle();
  bundle->surface_points.pop_back();
  bundle->surface_normals.pop_back();
  bundle->score_matrix.conservativeResize(3, Eigen::NoChange);
  return bundle;
}

Eigen::Isometry3d noTf(const std::string& frame, const char*) { throw Error("no frame " + frame); }

class ServerInstanceRequests : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { ros::Time::init(); }  // the responses' stamps, without a node

  static InformativenessServerRequests server(bool single, bool library) {
    ServedLibrary models;
    if (library) models = {{"mug", test::makeAxisBundle()}};
    return InformativenessServerRequests(single ? test::makeAxisBundle() : nullptr,
                                         InformativenessServerRosParameters{}, noTf, models);
  }

  static GetNextBestView::Response plan(InformativenessServerRequests& server,
                                        const std::string& instance) {
    GetNextBestView::Request request;
    request.sample_count = 20;
    request.sample_distance = 0.5;
    request.instance = instance;
    GetNextBestView::Response response;
    server.nextBestView(request, response);
    return response;
  }

  static GetHeatmap::Response heatmap(const InformativenessServerRequests& server,
                                      const std::string& instance) {
    GetHeatmap::Request request;
    request.mode = GetHeatmap::Request::MODE_VIEW_INDEX;
    request.instance = instance;
    GetHeatmap::Response response;
    server.getHeatmap(request, response);
    return response;
  }

  static double distanceOfBestFrom(const GetNextBestView::Response& response,
                                   const Eigen::Vector3d& centre) {
    const auto& p = response.best.pose.position;
    return (Eigen::Vector3d(p.x, p.y, p.z) - centre).norm();
  }
};

TEST_F(ServerInstanceRequests, ANamedInstanceIsPlannedAroundItsPoseWithItsBelief) {
  InformativenessServerRequests requests = server(true, true);
  requests.receiveInstances(scene());
  const GetNextBestView::Response response = plan(requests, "mug_2");
  ASSERT_TRUE(response.success) << response.message;
  EXPECT_NE(response.message.find("Instance mug_2 (model mug)"), std::string::npos)
      << response.message;
  EXPECT_NE(response.message.find("Belief of mug_2"), std::string::npos) << response.message;
  EXPECT_NEAR(distanceOfBestFrom(response, {0, 0, 1}), 0.5, 1e-6);  // sampled around mug_2
}

TEST_F(ServerInstanceRequests, MostUncertainIsPlannedForAndNamed) {
  InformativenessServerRequests requests = server(false, true);
  ObjectInstancesMsg latest = scene();
  latest.instances[1].model = "mug";  // box_1 plannable too: the tie goes to mug_2 by its id
  requests.receiveInstances(latest);
  const GetNextBestView::Response response = plan(requests, kMostUncertain);
  ASSERT_TRUE(response.success) << response.message;
  EXPECT_NE(response.message.find("Instance mug_2 (model mug, the most uncertain: cone90 50.0"),
            std::string::npos)
      << response.message;
  EXPECT_NEAR(distanceOfBestFrom(response, {0, 0, 1}), 0.5, 1e-6);
}

TEST_F(ServerInstanceRequests, AnEmptyInstanceKeepsTheOneObjectsAnswer) {
  InformativenessServerRequests requests = server(true, true);
  requests.receiveInstances(scene());
  const GetNextBestView::Response response = plan(requests, "");
  ASSERT_TRUE(response.success) << response.message;
  EXPECT_EQ(response.message.find("Instance"), std::string::npos) << response.message;
  EXPECT_NE(response.message.find("uniform belief"), std::string::npos) << response.message;
  EXPECT_NEAR(distanceOfBestFrom(response, {0, 0, 0}), 0.5, 1e-6);  // object_frame: no tf
}

TEST_F(ServerInstanceRequests, RequestsItCannotAnswerAreRefusedAndTheNextIsServed) {
  InformativenessServerRequests requests = server(true, true);
  const auto refused = [&](const std::string& instance, const std::string& words) {
    const GetNextBestView::Response response = plan(requests, instance);
    EXPECT_FALSE(response.success) << instance;
    EXPECT_NE(response.message.find(words), std::string::npos) << response.message;
    EXPECT_TRUE(response.ranked.poses.empty());
  };
  refused("mug_1", "No instances received yet");
  requests.receiveInstances(scene());
  refused("cup_1", "Unknown instance 'cup_1'");
  refused("box_1", "a model this server has not loaded (its ~models: mug)");
  ObjectInstancesMsg broken = scene();
  broken.instances[0].pose.pose.orientation.w = 2.0;
  requests.receiveInstances(broken);
  refused("mug_1", "non-unit orientation");
  EXPECT_TRUE(plan(requests, "mug_2").success);
}

TEST_F(ServerInstanceRequests, InstancesOutsideTheFixedFrameAreNotKept) {
  InformativenessServerRequests requests = server(true, true);
  ObjectInstancesMsg elsewhere = scene();
  elsewhere.header.frame_id = "camera";
  EXPECT_THROW(requests.receiveInstances(elsewhere), Error);
  EXPECT_NE(plan(requests, "mug_1").message.find("No instances received yet"), std::string::npos);
}

TEST_F(ServerInstanceRequests, WithoutALibraryAnInstanceIsRefusedWithoutAModelTheOneObject) {
  InformativenessServerRequests single = server(true, false);
  single.receiveInstances(scene());
  EXPECT_NE(plan(single, "mug_1").message.find("no model library"), std::string::npos);
  InformativenessServerRequests library_only = server(false, true);
  EXPECT_NE(plan(library_only, "").message.find("no single model"), std::string::npos);
  EXPECT_NE(heatmap(library_only, "").message.find("no single model"), std::string::npos);
  EXPECT_THROW(InformativenessServerRequests(nullptr, {}, noTf, {}), Error);
}

TEST_F(ServerInstanceRequests, AHeatmapForAnInstanceIsItsModelsInItsFrame) {
  ServedLibrary models = {{"mug", test::makeAxisBundle()}, {"box", boxBundle()}};
  InformativenessServerRequests requests(test::makeAxisBundle(), {}, noTf, models);
  requests.receiveInstances(scene());
  const GetHeatmap::Response box = heatmap(requests, "box_1");
  ASSERT_TRUE(box.success) << box.message;
  EXPECT_EQ(box.scores.size(), 3u);
  EXPECT_EQ(box.cloud.header.frame_id, "box_1");
  const GetHeatmap::Response own = heatmap(requests, "");
  ASSERT_TRUE(own.success) << own.message;
  EXPECT_EQ(own.scores.size(), 4u);
  EXPECT_EQ(own.cloud.header.frame_id, "object");
  EXPECT_FALSE(heatmap(requests, "cup_1").success);
}

}  // namespace
}  // namespace vdc

// ~query_instances without a node (instance_query.h): which remembered instances a request gets,
// and that every request it cannot match answers an empty list with a message saying why.
#include "instance_query.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace vdc {
namespace {

using view_direction_classification::ObjectInstance;
using view_direction_classification::QueryInstances;

ObjectInstance instanceMsg(std::uint32_t id, const std::string& name, const std::string& model,
                           bool gone = false) {
  ObjectInstance instance;
  instance.id = id;
  instance.name = name;
  instance.model = model;
  instance.state = gone ? ObjectInstance::GONE : ObjectInstance::PRESENT;
  instance.pose.pose.orientation.w = 1.0;
  return instance;
}

const std::vector<std::string> kModels = {"mug", "bowl"};

// mug_1 (id 1), bowl_1 (id 2, gone), mug_2 (id 4), listed out of id order as the memory may.
std::vector<ObjectInstance> memory() {
  return {instanceMsg(4, "mug_2", "mug"), instanceMsg(1, "mug_1", "mug"),
          instanceMsg(2, "bowl_1", "bowl", true)};
}

QueryInstances::Response ask(const std::string& model, int id, bool include_gone) {
  QueryInstances::Request request;
  request.model = model;
  request.id = id;
  request.include_gone = include_gone;
  QueryInstances::Response response;
  answerQuery(request, kModels, memory(), response);
  return response;
}

std::vector<std::string> names(const QueryInstances::Response& response) {
  std::vector<std::string> out;
  for (const ObjectInstance& instance : response.instances) out.push_back(instance.name);
  return out;
}

TEST(InstanceQuery, EmptyRequestListsThePresentInstancesInIdOrder) {
  const auto response = ask("", 0, false);
  EXPECT_EQ(names(response), (std::vector<std::string>{"mug_1", "mug_2"}));
  EXPECT_NE(response.message.find("1 gone not listed"), std::string::npos) << response.message;
}

TEST(InstanceQuery, GoneInstancesOnlyWhenAsked) {
  EXPECT_EQ(names(ask("", 0, true)), (std::vector<std::string>{"mug_1", "bowl_1", "mug_2"}));
  EXPECT_TRUE(ask("bowl", 0, false).instances.empty());
  EXPECT_EQ(names(ask("bowl", 0, true)), (std::vector<std::string>{"bowl_1"}));
  const auto by_id = ask("", 2, false);
  EXPECT_TRUE(by_id.instances.empty());
  EXPECT_NE(by_id.message.find("bowl_1 (id 2) is gone"), std::string::npos) << by_id.message;
  EXPECT_EQ(names(ask("", 2, true)), (std::vector<std::string>{"bowl_1"}));
}

TEST(InstanceQuery, ByModel) {
  const auto response = ask("mug", 0, true);
  EXPECT_EQ(names(response), (std::vector<std::string>{"mug_1", "mug_2"}));
  EXPECT_EQ(response.message, "2 instances of mug: mug_1, mug_2.");
}

TEST(InstanceQuery, ById) {
  const auto response = ask("", 4, false);
  EXPECT_EQ(names(response), (std::vector<std::string>{"mug_2"}));
  ASSERT_EQ(response.instances.size(), 1u);
  EXPECT_EQ(response.instances[0].id, 4u);
  EXPECT_EQ(names(ask("mug", 4, false)), (std::vector<std::string>{"mug_2"}));
}

TEST(InstanceQuery, KnownModelWithoutInstancesSaysSo) {
  QueryInstances::Request request;
  request.model = "bowl";
  QueryInstances::Response response;
  answerQuery(request, kModels, {instanceMsg(1, "mug_1", "mug")}, response);
  EXPECT_TRUE(response.instances.empty());
  EXPECT_EQ(response.message, "No instances of bowl remembered.");
}

TEST(InstanceQuery, UnknownModelAnswersEmptyWithTheLibrary) {
  const auto response = ask("teapot", 0, true);
  EXPECT_TRUE(response.instances.empty());
  EXPECT_EQ(response.message, "No model 'teapot' in the library (mug, bowl): no instances.");
}

TEST(InstanceQuery, UnknownIdOrAnIdOfAnotherModelAnswersEmpty) {
  const auto unknown = ask("", 99, true);
  EXPECT_TRUE(unknown.instances.empty());
  EXPECT_NE(unknown.message.find("No instance has id 99"), std::string::npos) << unknown.message;
  const auto other = ask("bowl", 1, true);
  EXPECT_TRUE(other.instances.empty());
  EXPECT_EQ(other.message, "Instance 1 is mug_1, a mug, not a bowl.");
}

TEST(InstanceQuery, BadRequestsAnswerEmptyWithAClearMessage) {
  const auto negative = ask("", -3, true);
  EXPECT_TRUE(negative.instances.empty());
  EXPECT_NE(negative.message.find("negative id (got -3)"), std::string::npos) << negative.message;
  // Any bytes, any length: the message quotes a printable prefix only.
  const std::string absurd = std::string(1000, 'x') + "\n\x01\xff";
  const auto long_name = ask(absurd, 0, true);
  EXPECT_TRUE(long_name.instances.empty());
  EXPECT_LT(long_name.message.size(), 200u);
  EXPECT_NE(long_name.message.find("(1003 bytes)"), std::string::npos) << long_name.message;
  const auto control = ask(std::string("m\0ug\n", 5), 0, true);
  EXPECT_TRUE(control.instances.empty());
  EXPECT_EQ(control.message.find('\n'), std::string::npos) << control.message;
}

TEST(InstanceQuery, EmptyMemory) {
  QueryInstances::Request request;
  QueryInstances::Response response;
  response.instances.push_back(instanceMsg(7, "stale_1", "mug"));  // a reused response is cleared
  answerQuery(request, kModels, {}, response);
  EXPECT_TRUE(response.instances.empty());
  EXPECT_EQ(response.message, "No instances remembered.");
}

}  // namespace
}  // namespace vdc

#pragma once

#include <view_direction_classification/ObjectInstance.h>
#include <view_direction_classification/QueryInstances.h>

#include <string>
#include <vector>

namespace vdc {

// ~query_instances without ROS transport: the instances of `reported` (what ~instances would
// list now, toObjectInstanceMsg) that the request asks for, in id order, and a message saying
// what was found or why nothing was. `models` are the library's names. Never fails: an unknown
// model or id, a gone instance without include_gone, a negative id or a model name no library
// holds all answer an empty list with a message (doc/nodes.md, "Asking the memory"). The caller
// sets the response's header.
void answerQuery(const view_direction_classification::QueryInstances::Request& request,
                 const std::vector<std::string>& models,
                 const std::vector<view_direction_classification::ObjectInstance>& reported,
                 view_direction_classification::QueryInstances::Response& response);

}  // namespace vdc

#include "instance_query.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <sstream>

namespace vdc {
namespace {

using ObjectInstanceMsg = view_direction_classification::ObjectInstance;
using Request = view_direction_classification::QueryInstances::Request;

// A requested name as a message may quote it: a request can carry any bytes, a reply to a
// terminal should not.
constexpr std::size_t kShownCharacters = 40;

std::string shown(const std::string& text) {
  std::string out = "'";
  for (std::size_t i = 0; i < text.size() && i < kShownCharacters; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    out += std::isprint(c) ? static_cast<char>(c) : '?';
  }
  if (text.size() > kShownCharacters) out += "...' (" + std::to_string(text.size()) + " bytes)";
  return text.size() > kShownCharacters ? out : out + "'";
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

bool isGone(const ObjectInstanceMsg& instance) { return instance.state == ObjectInstanceMsg::GONE; }

// Why the request cannot match anything whatever the memory holds; empty if it can.
std::string requestProblem(const Request& request, const std::vector<std::string>& models) {
  if (request.id < 0) {
    return "No instance has a negative id (got " + std::to_string(request.id) +
           "): ask for 0 (any) or an id from ~instances.";
  }
  if (request.model.empty() ||
      std::find(models.begin(), models.end(), request.model) != models.end()) {
    return "";
  }
  return "No model " + shown(request.model) + " in the library (" + joined(models) +
         "): no instances.";
}

// Why the instance the request names by id is not listed; empty if it is.
std::string idProblem(const Request& request, const std::vector<ObjectInstanceMsg>& reported) {
  const auto found = std::find_if(reported.begin(), reported.end(), [&](const auto& instance) {
    return static_cast<std::int64_t>(instance.id) == request.id;
  });
  if (found == reported.end()) {
    return "No instance has id " + std::to_string(request.id) +
           " (forgotten, never found, or not identified well enough to be reported).";
  }
  if (!request.model.empty() && found->model != request.model) {
    return "Instance " + std::to_string(request.id) + " is " + found->name + ", a " + found->model +
           ", not a " + request.model + ".";
  }
  if (isGone(*found) && !request.include_gone) {
    return found->name + " (id " + std::to_string(request.id) +
           ") is gone: its place was seen free. Set include_gone to get its last pose.";
  }
  return "";
}

bool matches(const Request& request, const ObjectInstanceMsg& instance) {
  if (!request.model.empty() && instance.model != request.model) return false;
  if (request.id != 0 && static_cast<std::int64_t>(instance.id) != request.id) return false;
  return request.include_gone || !isGone(instance);
}

std::string summary(const Request& request, const std::vector<ObjectInstanceMsg>& listed,
                    int gone_left_out) {
  std::ostringstream text;
  const std::string of = request.model.empty() ? "" : " of " + request.model;
  if (listed.empty()) {
    text << "No instances" << of << " remembered";
  } else {
    std::vector<std::string> names;
    for (const ObjectInstanceMsg& instance : listed) {
      names.push_back(instance.name + (isGone(instance) ? " (gone)" : ""));
    }
    text << listed.size() << (listed.size() == 1 ? " instance" : " instances") << of << ": "
         << joined(names);
  }
  if (gone_left_out > 0) {
    text << "; " << gone_left_out << " gone not listed (include_gone)";
  }
  text << ".";
  return text.str();
}

}  // namespace

void answerQuery(const Request& request, const std::vector<std::string>& models,
                 const std::vector<ObjectInstanceMsg>& reported,
                 view_direction_classification::QueryInstances::Response& response) {
  response.instances.clear();
  std::string problem = requestProblem(request, models);
  if (problem.empty() && request.id != 0) problem = idProblem(request, reported);
  if (!problem.empty()) {
    response.message = problem;
    return;
  }
  int gone_left_out = 0;
  for (const ObjectInstanceMsg& instance : reported) {
    if (matches(request, instance)) {
      response.instances.push_back(instance);
    } else if (isGone(instance) && !request.include_gone) {
      Request with_gone = request;
      with_gone.include_gone = true;
      if (matches(with_gone, instance)) ++gone_left_out;
    }
  }
  std::sort(response.instances.begin(), response.instances.end(),
            [](const auto& a, const auto& b) { return a.id < b.id; });
  response.message = summary(request, response.instances, gone_left_out);
}

}  // namespace vdc

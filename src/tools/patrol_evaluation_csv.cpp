#include "patrol_evaluation_csv.h"

#include <cstdio>
#include <functional>
#include <vector>

namespace vdc::tools {

namespace {

std::string label(PatrolChangeKind kind, const std::string& model, int object) {
  return std::string(patrolChangeKindName(kind)) + ":" + model + "#" + std::to_string(object);
}

std::string number(double value) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.1f", value);
  return text;
}

// The notices of the changes made before `pass`, in the order made.
std::vector<ChangeNotice> noticesOf(const PatrolResult& result, int pass) {
  std::vector<ChangeNotice> notices;
  for (const ChangeNotice& notice : result.notices) {
    if (notice.pass == pass) notices.push_back(notice);
  }
  return notices;
}

std::string joinedNotices(const std::vector<ChangeNotice>& notices,
                          const std::function<std::string(const ChangeNotice&)>& cell) {
  std::string text;
  for (const ChangeNotice& notice : notices) text += (text.empty() ? "" : ";") + cell(notice);
  return text;
}

std::string viewsOr(const ChangeNotice& notice, int views) {
  if (notice.superseded) return "superseded";
  return notice.noticed ? std::to_string(views) : "-";
}

struct Column {
  const char* name;
  std::function<std::string(const PatrolPassRecord&, const std::vector<ChangeNotice>&)> cell;
};

std::string count(int value) { return std::to_string(value); }

const std::vector<Column>& columns() {
  using Notices = std::vector<ChangeNotice>;
  static const std::vector<Column> kColumns = {
      {"pass", [](const auto& r, const Notices&) { return count(r.pass); }},
      {"views", [](const auto& r, const Notices&) { return count(r.views); }},
      {"changes",
       [](const auto& r, const Notices&) {
         std::string text;
         for (const PatrolChange& c : r.changes) {
           text += (text.empty() ? "" : ";") + patrolChangeLabel(c);
         }
         return text;
       }},
      {"present", [](const auto& r, const Notices&) { return count(r.metrics.present); }},
      {"confirmed", [](const auto& r, const Notices&) { return count(r.metrics.confirmed); }},
      {"right", [](const auto& r, const Notices&) { return count(r.metrics.right); }},
      {"duplicates", [](const auto& r, const Notices&) { return count(r.metrics.duplicates); }},
      {"stale", [](const auto& r, const Notices&) { return count(r.metrics.stale); }},
      {"max_duplicates", [](const auto& r, const Notices&) { return count(r.max_duplicates); }},
      {"max_stale", [](const auto& r, const Notices&) { return count(r.max_stale); }},
      {"instances", [](const auto& r, const Notices&) { return count(r.instances); }},
      {"gone_instances", [](const auto& r, const Notices&) { return count(r.gone_instances); }},
      {"objects_ever", [](const auto& r, const Notices&) { return count(r.objects_ever); }},
      {"mean_time_ms", [](const auto& r, const Notices&) { return number(r.mean_time_ms); }},
      {"max_time_ms", [](const auto& r, const Notices&) { return number(r.max_time_ms); }},
      {"notice_changes",
       [](const auto&, const Notices& n) {
         return joinedNotices(
             n, [](const ChangeNotice& c) { return label(c.kind, c.model, c.object); });
       }},
      {"notice_views",
       [](const auto&, const Notices& n) {
         return joinedNotices(n, [](const ChangeNotice& c) { return viewsOr(c, c.views); });
       }},
      {"notice_place_views",
       [](const auto&, const Notices& n) {
         return joinedNotices(n, [](const ChangeNotice& c) { return viewsOr(c, c.place_views); });
       }},
  };
  return kColumns;
}

}  // namespace

std::string patrolChangeLabel(const PatrolChange& change) {
  return label(change.kind, change.model, change.object);
}

void writePatrolCsv(std::ostream& out, const PatrolResult& result) {
  const auto& all = columns();
  for (std::size_t c = 0; c < all.size(); ++c) out << (c ? "," : "") << all[c].name;
  out << "\n";
  for (const PatrolPassRecord& record : result.passes) {
    const std::vector<ChangeNotice> notices = noticesOf(result, record.pass);
    for (std::size_t c = 0; c < all.size(); ++c) {
      out << (c ? "," : "") << all[c].cell(record, notices);
    }
    out << "\n";
  }
}

}  // namespace vdc::tools

#include "select_record_json.h"

#include <algorithm>
#include <cmath>

namespace gmcc::cli {
namespace {

// JSON text appended to one string, in nlohmann::json's number format.
struct Writer {
  std::string out;

  void raw(const char* text) { out += text; }
  void number(double x) {
    if (!std::isfinite(x)) {  // as nlohmann::json writes a non-finite double
      out += "null";
      return;
    }
    char buffer[64];  // nlohmann::json's own formatting (grisu2), as its dump() writes a double
    const char* end = nlohmann::detail::to_chars(buffer, buffer + sizeof buffer, x);
    out.append(buffer, static_cast<std::size_t>(end - buffer));
  }
  void integer(std::size_t n) { out += std::to_string(n); }
  void string(const std::string& s) { out += Json(s).dump(-1, ' ', false, Json::error_handler_t::replace); }
  void pair(const std::array<double, 2>& p) {
    raw("[");
    number(p[0]);
    raw(",");
    number(p[1]);
    raw("]");
  }
  void angle(const char* key, const std::optional<Enclosure>& a) {  // null when absent
    out += key;
    if (a) number(a->mid);
    else raw("null");
  }
};

std::array<double, 2> mids(const std::array<Enclosure, 2>& p) { return {p[0].mid, p[1].mid}; }

void feasible_set(Writer& w, const SelectRecord& r) {
  w.raw(",\"feasible_set\":{\"kind\":");
  w.string(to_string(r.kind));
  w.raw(",\"vertices\":[");
  double radius = 0;
  for (std::size_t i = 0; i < r.vertices.size(); ++i) {
    if (i) w.raw(",");
    w.pair(mids(r.vertices[i]));
    radius = std::max({radius, r.vertices[i][0].rad, r.vertices[i][1].rad});
  }
  w.raw("],\"vertex_radius\":");
  w.number(radius);
  if (r.kind == ConvexKind::empty) {
    w.raw(",\"reason\":");
    w.string(r.empty_reason);
  }
  w.raw("}");
}

void selections(Writer& w, const SelectRecord& r) {
  w.raw(",\"selections\":{");
  bool first = true;
  for (Rule rule : all_rules) {
    if (!r.selections[rule]) continue;
    const RecordSelection& s = *r.selections[rule];
    w.raw(first ? "\"" : ",\"");
    first = false;
    w.raw(to_string(rule).c_str());
    w.raw("\":{\"map\":");
    w.pair(mids(s.map));
    w.raw(",\"map_radius\":");
    w.pair({s.map[0].rad, s.map[1].rad});
    w.raw(",\"worst_case_deg\":");
    w.number(s.worst_case_deg.mid);
    if (s.worst_case_illuminant_deg) {
      w.raw(",\"worst_case_illuminant_deg\":");
      w.number(s.worst_case_illuminant_deg->mid);
    }
    w.raw("}");
  }
  w.raw("}");
}

void truth(Writer& w, const RecordTruth& t) {
  w.raw(",\"truth\":{\"in_feasible_set\":");
  w.raw(t.in_feasible_set ? "true" : "false");
  w.raw(",\"errors\":{");
  bool first = true;
  for (Rule rule : all_rules) {
    if (!t.errors[rule]) continue;
    const RecordErrors& e = *t.errors[rule];
    w.raw(first ? "\"" : ",\"");
    first = false;
    w.raw(to_string(rule).c_str());
    w.raw("\":{\"map_error_deg\":");
    w.number(e.map_error_deg.mid);
    w.angle(",\"illuminant_error_deg\":", e.illuminant_error_deg);
    w.angle(",\"reproduction_error_deg\":", e.reproduction_error_deg);
    w.raw("}");
  }
  w.raw("}}");
}

}  // namespace

std::string record_text(std::size_t line, const Json& id, const SelectRecord& r) {
  Writer w;
  w.out.reserve(1024);
  w.raw("{\"line\":");
  w.integer(line);
  if (!id.is_null()) {
    w.raw(",\"id\":");
    w.out += id.dump(-1, ' ', false, Json::error_handler_t::replace);
  }
  w.raw(",\"record\":");
  w.integer(static_cast<std::size_t>(scene_record_version));
  w.raw(",\"input\":{\"image_colours\":");
  w.integer(r.image_colours);
  w.raw(",\"image_dropped_nonpositive_blue\":");
  w.integer(r.image_dropped);
  w.raw("}");
  feasible_set(w, r);
  if (r.illuminants) {
    w.raw(",\"constraint\":{\"illuminants\":");
    w.integer(r.illuminants);
    w.raw("}");
  }
  if (r.recovery) {
    w.raw(",\"recovery\":{\"policy\":");
    w.string(to_string(r.recovery->policy));
    w.raw(r.recovery->applied ? ",\"applied\":true,\"reason\":" : ",\"applied\":false,\"reason\":");
    w.string(r.recovery->reason);
    w.raw("}");
  }
  if (r.kind != ConvexKind::empty) selections(w, r);
  if (r.truth) truth(w, *r.truth);
  w.raw("}\n");
  return std::move(w.out);
}

}  // namespace gmcc::cli

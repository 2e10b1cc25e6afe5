#include "select_record_json.h"

#include <algorithm>

namespace gmcc::cli {
namespace {

// A pair of enclosures as [mid, mid] and, in `radius`, [rad, rad].
Json mids(const std::array<Enclosure, 2>& p) { return Json::array({p[0].mid, p[1].mid}); }
Json radii(const std::array<Enclosure, 2>& p) { return Json::array({p[0].rad, p[1].rad}); }

// An angle: its midpoint, within the contract's accuracy of the exact angle; null when absent.
Json angle(const std::optional<Enclosure>& a) { return a ? Json(a->mid) : Json(); }

Json feasible_json(const SelectRecord& r) {
  Json f;
  f["kind"] = to_string(r.kind);
  Json vertices = Json::array();
  double radius = 0;
  for (const auto& v : r.vertices) {
    vertices.push_back(mids(v));
    radius = std::max({radius, v[0].rad, v[1].rad});
  }
  f["vertices"] = std::move(vertices);
  f["vertex_radius"] = radius;
  if (r.kind == ConvexKind::empty) f["reason"] = r.empty_reason;
  return f;
}

}  // namespace

Json record_json(const SelectRecord& r) {
  Json j;
  j["record"] = scene_record_version;
  j["input"] = {{"image_colours", r.image_colours}, {"image_dropped_nonpositive_blue", r.image_dropped}};
  j["feasible_set"] = feasible_json(r);
  if (r.illuminants) j["constraint"] = {{"illuminants", r.illuminants}};
  if (r.recovery)
    j["recovery"] = {{"policy", to_string(r.recovery->policy)}, {"applied", r.recovery->applied},
                     {"reason", r.recovery->reason}};
  if (r.kind != ConvexKind::empty) {
    Json& s = j["selections"];
    for (Rule rule : all_rules) {
      if (!r.selections[rule]) continue;
      const RecordSelection& x = *r.selections[rule];
      Json one = {{"map", mids(x.map)}, {"map_radius", radii(x.map)}, {"worst_case_deg", x.worst_case_deg.mid}};
      if (x.worst_case_illuminant_deg) one["worst_case_illuminant_deg"] = x.worst_case_illuminant_deg->mid;
      s[to_string(rule)] = std::move(one);
    }
  }
  if (r.truth) {
    Json t;
    t["in_feasible_set"] = r.truth->in_feasible_set;
    Json errors = Json::object();
    for (Rule rule : all_rules)
      if (const auto& e = r.truth->errors[rule])
        errors[to_string(rule)] = {{"map_error_deg", e->map_error_deg.mid},
                                   {"illuminant_error_deg", angle(e->illuminant_error_deg)},
                                   {"reproduction_error_deg", angle(e->reproduction_error_deg)}};
    t["errors"] = std::move(errors);
    j["truth"] = std::move(t);
  }
  return j;
}

}  // namespace gmcc::cli

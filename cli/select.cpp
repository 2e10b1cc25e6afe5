#include "select.h"

#include "integer_option.h"
#include "json_output.h"
#include "select_3d.h"
#include "write_stdout.h"

#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/illumination_constraint.h>
#include <gmcc/geometry/intersection.h>
#include <gmcc/validation/colour_csv.h>

namespace gmcc::cli {
namespace {

// Largest coordinate accepted for chromaticities, gamuts and maps: far beyond any physical
// value, and small enough that every number gmcc reports as a double (coordinates, enclosures
// rounded outward, areas up to 1e300) stays finite.
const Rational& max_coordinate() {
  static const Rational limit = parse_rational("1e150");
  return limit;
}
bool within_limit(const Point2& p) { return p.x <= max_coordinate() && p.y <= max_coordinate(); }

// Chromaticities of a colour file under the blue policy, with line-accurate errors.
Chromaticities chromaticities_of(const ColourTable& table, NonPositiveBluePolicy policy) {
  Chromaticities c;
  try {
    c = perspective_chromaticities(table.colours, policy);
  } catch (const NonPositiveBlue& e) {
    throw InputError(table.file, table.lines[e.index],
                     "b <= 0: this colour has no perspective chromaticity (r/b, g/b); "
                     "use --nonpositive-blue drop to skip such colours");
  }
  if (c.points.empty())
    throw InputError(table.file, 0,
                     "no usable colour: every colour has b = 0 and so no chromaticity");
  for (std::size_t i = 0; i < c.points.size(); ++i)
    if (!within_limit(c.points[i]))
      throw InputError(table.file, table.lines[c.source_index[i]],
                       "the chromaticity r/b or g/b exceeds 1e150, the largest gmcc accepts "
                       "(it reports doubles): is b nearly 0?");
  return c;
}

constexpr std::size_t kMaxMinViolationEdges = 2000;

// --on-empty: when F is empty, apply the policy and replace F by what it recovers.
RecoveryReport recover(const std::string& policy, const Expansion& expansion,
                       const std::vector<Point2>& canonical, const std::vector<Point2>& image,
                       SelectReport& r) {
  RecoveryReport rec;
  rec.policy = policy;
  if (r.feasible.kind != ConvexKind::empty) return rec;
  rec.reason = r.empty_reason;
  const std::optional<ConvexSet2> C =
      r.constraint ? std::optional<ConvexSet2>(r.constraint->maps) : std::nullopt;
  if (policy == "grow-canonical") {
    if (expansion.policy == ExpansionPolicy::centroid_clip)
      throw InputError("--on-empty", 0,
                       "grow-canonical grows the gamut by the multiplicative policy; it cannot "
                       "continue a centroid-clip expansion (use --expand-policy multiplicative)");
    GrowCanonicalOptions g;
    g.start = expansion.factor;
    rec.precision = g.precision;
    rec.grown = grow_canonical_until_feasible(canonical, image, C, g);
    if (!rec.grown->found) return rec;
    r.feasible = rec.grown->feasible;
  } else {
    // min_violation clips its minimisers edge by edge in rationals: O(k·m²) for m gamut edges and
    // k image hull vertices (2000 edges, 3 image vertices: about 13 s; 6000: 150 s). Refused up
    // front beyond kMaxMinViolationEdges (docs/cli.md "Resource limits").
    if (r.canonical_gamut.vertices.size() > kMaxMinViolationEdges)
      throw InputError("--on-empty", 0,
                       "min-violation takes canonical gamuts of at most " +
                           std::to_string(kMaxMinViolationEdges) + " vertices; this one has " +
                           std::to_string(r.canonical_gamut.vertices.size()) +
                           " (grow-canonical has no such limit)");
    rec.min_violation = min_violation(r.canonical_gamut, image, C);
    r.feasible = rec.min_violation->feasible;
  }
  rec.applied = true;
  r.empty_reason.clear();
  return rec;
}

}  // namespace

CLI::App* add_select_command(CLI::App& app, SelectOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "select",
      "Feasible set of perspective diagonal maps for an image and a canonical gamut, and the "
      "three selection rules of Finlayson & Hordley (1999): max-area, 2-D mean, 3-D mean.");
  cmd->add_option("--canonical", o.canonical_path,
                  "canonical colours, one r,g,b per line (decimal or p/q, read exactly)")
      ->required();
  cmd->add_option("--image", o.image_path, "image colours, same format")->required();
  cmd->add_flag("--json", o.json, "print one JSON object (docs/cli.md, \"JSON output\") instead of a summary");
  cmd->add_option("--expand", o.expand_factor,
                  "expand the canonical gamut by this factor (0.1 = 10%; exact)")
      ->capture_default_str();
  cmd->add_option("--expand-policy", o.expand_policy, "none | centroid-clip | multiplicative")
      ->check(CLI::IsMember({"none", "centroid-clip", "multiplicative"}))
      ->capture_default_str();
  cmd->add_option("--mean3d", o.mean3d_method,
                  "route to the 3-D mean: analytic (closed form, certified bound), quadrature "
                  "(Duffy–Gauss–Legendre, estimated error) or monte-carlo (the paper's method, "
                  "standard error)")
      ->check(CLI::IsMember({"analytic", "quadrature", "monte-carlo"}))
      ->capture_default_str();
  cmd->add_option("--precision", o.precision_bits,
                  "analytic: force one MPFI evaluation at this many bits, 53 to 2^20 "
                  "(default 0: automatic)");
  cmd->add_option("--order", o.order, "quadrature: Gauss–Legendre points per direction, 1 to 256")
      ->capture_default_str();
  cmd->add_option("--samples", o.samples, "monte-carlo: points drawn in the unit cube, 1 to 10^9")
      ->capture_default_str();
  cmd->add_option("--seed", o.seed, "monte-carlo: seed of the mt19937_64 generator, 0 to 2^64-1")
      ->capture_default_str();
  cmd->add_option("--canonical-illuminant", o.canonical_illuminant,
                  "r,g,b of the canonical light, for the illuminant-space worst case "
                  "(e = c ⊘ d; exact numbers, all > 0)")
      ->capture_default_str();
  cmd->add_option("--nonpositive-blue", o.nonpositive_blue,
                  "colours with b <= 0 have no chromaticity: drop (count them) or reject")
      ->check(CLI::IsMember({"drop", "reject"}))
      ->capture_default_str();
  cmd->add_option("--illuminants", o.illuminants_path,
                  "plausible lights, one r,g,b per line (as the camera sees them): keep only the "
                  "maps in the convex hull of their maps c ⊘ e (Finlayson 1996)");
  cmd->add_option("--on-empty", o.on_empty,
                  "when F is empty: none (report it), grow-canonical (least multiplicative "
                  "expansion of the canonical gamut, by bisection) or min-violation (maps of least "
                  "Chebyshev violation, exact LP)")
      ->check(CLI::IsMember({"none", "grow-canonical", "min-violation"}))
      ->capture_default_str();
  cmd->add_option("--space", o.space,
                  "2d: perspective maps (d1/d3, d2/d3), the paper's rules; 3d: Forsyth's CRULE, "
                  "diagonal maps (d1, d2, d3) as an exact polytope, max-volume and centroid")
      ->check(CLI::IsMember({"2d", "3d"}))
      ->capture_default_str();
  cmd->add_option("--black", o.black, "3d: include or exclude black (0,0,0) in the canonical gamut")
      ->check(CLI::IsMember({"include", "exclude"}))
      ->capture_default_str();
  return cmd;
}

SelectSettings select_settings(const SelectOptions& o) {
  SelectSettings s;
  s.json = o.json;
  s.on_empty = o.on_empty;
  s.nonpositive_blue =
      o.nonpositive_blue == "reject" ? NonPositiveBluePolicy::reject : NonPositiveBluePolicy::drop;
  try {
    s.expansion.policy = expansion_policy_from_string(o.expand_policy);
    s.expansion.factor = parse_rational(o.expand_factor);
    if (sgn(s.expansion.factor) < 0) throw std::invalid_argument("must be >= 0");
    if (sgn(s.expansion.factor) > 0 && s.expansion.policy == ExpansionPolicy::none)
      throw std::invalid_argument("needs --expand-policy centroid-clip or multiplicative");
  } catch (const std::invalid_argument& e) {
    throw InputError("--expand", 0, e.what());
  }
  try {
    const ColourTable c = parse_colour_csv(o.canonical_illuminant, "--canonical-illuminant");
    if (c.colours.size() != 1) throw InputError("--canonical-illuminant", 0, "expected one r,g,b");
    s.canonical_illuminant = c.colours[0];
    for (const Rational* x : {&s.canonical_illuminant.r, &s.canonical_illuminant.g, &s.canonical_illuminant.b})
      if (sgn(*x) <= 0) throw InputError("--canonical-illuminant", 0, "every channel must be > 0");
  } catch (const InputError& e) {
    // Keep the reader's reason (a digit limit, a malformed number, a channel <= 0), without its
    // "--canonical-illuminant:1:" prefix.
    std::string why = e.what();
    const std::string prefix = e.file() + (e.line() ? ":" + std::to_string(e.line()) : "") + ": ";
    if (why.compare(0, prefix.size(), prefix) == 0) why.erase(0, prefix.size());
    throw InputError("--canonical-illuminant", 0,
                     quoted_text(o.canonical_illuminant) + " is not a light r,g,b with channels > 0: " + why);
  }

  s.mean3d.method = mean3d_method_from_string(o.mean3d_method);
  s.mean3d.precision_bits = static_cast<unsigned>(integer_option("--precision", o.precision_bits, 0, 1u << 20));
  if (s.mean3d.precision_bits != 0 && s.mean3d.precision_bits < 53)
    throw InputError("--precision", 0, "must be 0 (automatic) or from 53 to 1048576 bits");
  s.mean3d.order = static_cast<unsigned>(integer_option("--order", o.order, 1, 256));
  s.mean3d.samples = integer_option("--samples", o.samples, 1, 1000000000);
  s.mean3d.seed = integer_option("--seed", o.seed, 0, ~std::uint64_t(0));
  return s;
}

std::string select_output(const SelectSettings& s, const ColourTable& canonical,
                          const ColourTable& image, const ColourTable* illuminants) {
  SelectReport r;
  r.expansion = s.expansion;
  r.canonical_illuminant = s.canonical_illuminant;
  const Chromaticities cq = chromaticities_of(canonical, s.nonpositive_blue);
  const Chromaticities iq = chromaticities_of(image, s.nonpositive_blue);
  r.canonical_colours = canonical.colours.size();
  r.canonical_dropped = cq.dropped;
  r.image_colours = image.colours.size();
  r.image_dropped = iq.dropped;

  r.canonical_gamut = canonical_gamut(cq.points, s.expansion);
  for (const Point2& v : r.canonical_gamut.vertices)
    if (!within_limit(v))
      throw InputError("--expand", 0,
                       "the expanded canonical gamut exceeds 1e150, the largest coordinate "
                       "gmcc accepts (it reports doubles)");
  try {
    r.feasible = feasible_set(r.canonical_gamut, iq.points);
  } catch (const UnboundedFeasibleSet& e) {
    throw InputError(image.file, 0, e.what());
  }
  // F's coordinates are canonical over image chromaticities: both within the limit can still
  // give maps beyond it.
  for (const Point2& v : r.feasible.vertices)
    if (!within_limit(v))
      throw InputError(image.file, 0,
                       "against the canonical gamut of " + canonical.file +
                           ", the feasible maps exceed 1e150, the largest coordinate gmcc "
                           "accepts (it reports doubles): the canonical chromaticities are "
                           "that much larger than this image's");
  if (illuminants) {
    ConstraintReport c;
    c.illuminants = illuminants->colours.size();
    try {
      c.maps = illumination_constraint(illuminants->colours, r.canonical_illuminant);
    } catch (const NonPositiveIlluminant& e) {
      throw InputError(illuminants->file, illuminants->lines[e.index],
                       "an illuminant needs every channel > 0 (its map c ⊘ e is undefined)");
    }
    c.unconstrained = r.feasible;
    // F ∩ C in the feasible set's own convex pass (C's edges as extra lines): linear in |C|,
    // where intersecting the finished F with C cost O(|F|·|C|) (issue 13).
    r.feasible = feasible_set(CanonicalConstraints(r.canonical_gamut, c.maps), iq.points);
    r.constraint = std::move(c);
  }
  if (r.feasible.kind == ConvexKind::empty)
    r.empty_reason = r.constraint && r.constraint->unconstrained.kind != ConvexKind::empty
                         ? "the feasible set is not empty, but it holds no map of a plausible "
                           "illuminant (--illuminants)"
                         : "no diagonal map takes every image colour into the canonical gamut";
  if (s.on_empty != "none") r.recovery = recover(s.on_empty, s.expansion, cq.points, iq.points, r);
  r.selections = select_maps(r.feasible, {s.mean3d, r.canonical_illuminant});
  return s.json ? select_json(r) : select_text(r);
}

int run_select(const SelectOptions& o) {
  if (o.space == "3d") return run_select_3d(o);
  const SelectSettings settings = select_settings(o);
  const ColourTable canonical = read_colour_csv(o.canonical_path);
  const ColourTable image = read_colour_csv(o.image_path);
  std::optional<ColourTable> illuminants;
  if (!o.illuminants_path.empty()) illuminants = read_colour_csv(o.illuminants_path);
  write_stdout(select_output(settings, canonical, image, illuminants ? &*illuminants : nullptr));
  return 0;
}

}  // namespace gmcc::cli

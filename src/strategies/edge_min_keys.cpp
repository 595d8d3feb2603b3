#include "strategies/edge_min_keys.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "io/number_format.hpp"
#include "settings/value_text.hpp"
#include "strategies/range_keys.hpp"

namespace fragsim {
namespace {

// Each edge weight must be finite and in the library's range, not all zero.
std::optional<std::string> edge_weights_rule(const std::array<double, 4>& w) {
  const ParamRange& each = library_range(kEdgeMinRanges, "edge_weights");
  for (double v : w) {
    if (!std::isfinite(v)) return std::string("each weight must be finite");
    if (!each.admits(v)) return "each weight " + key_range(each).text();
  }
  if (!some_edge_allowed(w)) return std::string("at least one weight must be > 0");
  return std::nullopt;
}

// 'top bottom left right' holds four weights, the key's own type (no other key has four numbers).
settings::Key<EdgeMinParams> edge_weights_key() {
  using P = EdgeMinParams;
  return {"edge_weights",
          settings::help_text({"top bottom left right",
                               "weight of each screen edge as a way out: the push chosen is the "
                               "least push divided by its edge's weight; 0 forbids an edge (not "
                               "all four)"}),
          [](P& o, const std::string& text) {
            std::istringstream in(text);
            std::array<double, 4> w{};
            std::string word;
            int n = 0;
            while (in >> word) {
              if (n == 4) throw settings::ValueError{"expected four numbers top bottom left right"};
              w[static_cast<std::size_t>(n++)] = settings::parse_double(word);
            }
            if (n != 4) throw settings::ValueError{"expected four numbers top bottom left right"};
            if (auto rule = edge_weights_rule(w)) throw settings::ValueError{*rule};
            o.edge_weights = w;
          },
          [](const P& o) {
            std::string out;
            for (double v : o.edge_weights) out += (out.empty() ? "" : " ") + format_double(v);
            return out;
          },
          [](const P& o) { return edge_weights_rule(o.edge_weights); }};
}

}  // namespace

const ParamSpec<EdgeMinParams>& edge_min_param_spec() {
  using namespace settings;
  using P = EdgeMinParams;
  const auto& r = kEdgeMinRanges;
  static const ParamSpec<P> spec{
      {ranged_real(r, "margin_m", "m", "clearance kept beyond the protected rectangle's edge",
                   &P::margin_m),
       ranged_real(r, "a_max_mps2", "m/s^2", "cap on the imposed acceleration", &P::a_max_mps2),
       choice("camera_model",
              "what the camera is assumed to do before a fragment arrives: keep its velocity "
              "and view, change them within acceleration and turn-rate bounds, or go anywhere "
              "within V_c t",
              &P::camera_model,
              {{"constant", CameraModel::kConstant},
               {"bounded_accel", CameraModel::kBoundedAccel},
               {"reachable", CameraModel::kReachable}}),
       ranged_real(r, "camera_accel_mps2", "m/s^2",
                   "bounded_accel: the camera's acceleration bound assumed when the scene "
                   "declares none (mode = path or track)",
                   &P::camera_accel_mps2),
       ranged_real(r, "camera_turn_degps", "degrees/s",
                   "bounded_accel and reachable: the camera's turn-rate bound assumed when the "
                   "scene declares none; inf: no bound (every orientation at once)",
                   &P::camera_turn_degps),
       ranged_real(r, "horizon_cap_s", "s",
                   "look-ahead cap: a path is examined until the fragment reaches the ground, at "
                   "most this far ahead",
                   &P::horizon_cap_s),
       ranged_integer(r, "max_solves", "",
                      "fragments solved exactly per step, the most urgent first; the rest keep "
                      "their last force (0: no cap)",
                      &P::max_solves),
       edge_weights_key(),
       ranged_real(r, "cover_max", "",
                   "occlusion bound: the share of the central region debris may be predicted to "
                   "cover; the fragments covering most are pushed out of it (1: off)",
                   &P::cover_max),
       ranged_real(r, "cover_region", "",
                   "cover_max: the central region's share of the screen's width and height (set "
                   "it as metrics.central_share)",
                   &P::cover_region),
       ranged_real(r, "cover_horizon_s", "s", "cover_max: how far ahead coverage is predicted",
                   &P::cover_horizon_s),
       ranged_integer(r, "cover_samples", "",
                      "cover_max: predicted steps per doubling of the lead: every step for the "
                      "first 2 B, every 2nd for the next 2 B steps, every 4th for the next 4 B, "
                      "...",
                      &P::cover_samples),
       ranged_integer(r, "cover_cells", "",
                      "cover_max: cells across the central region's width in the predicted "
                      "coverage grid (rows follow the aspect)",
                      &P::cover_cells),
       ranged_real(r, "cover_margin", "",
                   "cover_max: how far under the bound the prediction aims, for its own error "
                   "(discs and coarse cells against the metric's boxes and pixels)",
                   &P::cover_margin)},
      {}};
  return spec;
}

}  // namespace fragsim

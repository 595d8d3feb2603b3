#include "strategies/edge_min_params.hpp"

#include <cmath>
#include <sstream>

#include "settings/value_text.hpp"

namespace fragsim {
namespace {

// 'top bottom left right': four weights, the key's own type (no other key has four numbers).
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

std::optional<std::string> edge_weights_rule(const std::array<double, 4>& w) {
  bool any = false;
  for (double v : w) {
    if (!std::isfinite(v)) return std::string("each weight must be finite");
    if (!(v >= 0.0 && v <= 1e6)) return std::string("each weight must be in [0, 1e+06]");
    any = any || v > 0.0;
  }
  if (!any) return std::string("at least one weight must be > 0");
  return std::nullopt;
}

const ParamSpec<EdgeMinParams>& edge_min_param_spec() {
  using namespace settings;
  using P = EdgeMinParams;
  // The assumed camera bounds stand in for a scene that declares none: the acceleration must be
  // a number to reason with (a camera that accelerates without bound is `reachable`'s case); the
  // turn rate may be inf, as every orientation is bounded by the ball around the eye.
  static const ParamSpec<P> spec{
      {real("margin_m", "m", "clearance kept beyond the protected rectangle's edge", &P::margin_m,
            closed(0, 100)),
       real("a_max_mps2", "m/s^2", "cap on the imposed acceleration", &P::a_max_mps2,
            closed(0, 1e9)),
       choice("camera_model",
              "what the camera is assumed to do before a fragment arrives: keep its velocity "
              "and view, change them within acceleration and turn-rate bounds, or go anywhere "
              "within V_c t",
              &P::camera_model,
              {{"constant", CameraModel::kConstant},
               {"bounded_accel", CameraModel::kBoundedAccel},
               {"reachable", CameraModel::kReachable}}),
       real("camera_accel_mps2", "m/s^2",
            "bounded_accel: the camera's acceleration bound assumed when the scene declares "
            "none (mode = path or track)",
            &P::camera_accel_mps2, closed(0, 1e6)),
       real_or_inf("camera_turn_degps", "degrees/s",
                   "bounded_accel and reachable: the camera's turn-rate bound assumed when the "
                   "scene declares none; inf: no bound (every orientation at once)",
                   &P::camera_turn_degps, closed(0, 1e6)),
       real("horizon_cap_s", "s",
            "look-ahead cap: a path is examined until the fragment reaches the ground, at most "
            "this far ahead",
            &P::horizon_cap_s, open_closed(0, 3600)),
       integer("max_solves", "",
               "fragments solved exactly per step, the most urgent first; the rest keep their "
               "last force (0: no cap)",
               &P::max_solves, 0, 100000000),
       edge_weights_key(),
       real("cover_max", "",
            "occlusion bound: the share of the central region debris may be predicted to cover; "
            "the fragments covering most are pushed out of it (1: off)",
            &P::cover_max, closed(0, 1)),
       real("cover_region", "",
            "cover_max: the central region's share of the screen's width and height (set it as "
            "metrics.central_share)",
            &P::cover_region, open_closed(0, 1)),
       real("cover_horizon_s", "s", "cover_max: how far ahead coverage is predicted",
            &P::cover_horizon_s, open_closed(0, 10)),
       integer("cover_samples", "",
               "cover_max: predicted steps per doubling of the lead: every step for the first "
               "2 B, every 2nd for the next 2 B steps, every 4th for the next 4 B, ...",
               &P::cover_samples, 1, 120),
       integer("cover_cells", "",
               "cover_max: cells across the central region's width in the predicted coverage "
               "grid (rows follow the aspect)",
               &P::cover_cells, 2, 256),
       real("cover_margin", "",
            "cover_max: how far under the bound the prediction aims, for its own error (discs "
            "and coarse cells against the metric's boxes and pixels)",
            &P::cover_margin, closed(0, 0.5))},
      {}};
  return spec;
}

}  // namespace fragsim

#pragma once
// The logarithmic perspective projection kind (Lloyd, Govindaraju, Quammen, Molnar and Manocha,
// "Logarithmic Perspective Shadow Maps", ACM TOG 27(4) 2008; Lloyd's thesis calls it F_lp): a
// perspective projection followed by a logarithmic transformation of one of its axes. A world point p under the
// map's perspective 4x4, h = world_to_uvz (p, 1), lands at u = h.x / h.w and depth h.z / h.w, as under
// a linear map; its v is the logarithm of h.w, the distance from the perspective's centre along the
// view: v = log(w / near) / log(far / near). In post-perspective terms, with the perspective's own
// v_p = (1 - near / w) far / (far - near), v = log(1 - (1 - near / far) v_p) / log(near / far): the
// form c0 log(c1 v_p + c2). Light rays keep their w (the warp looks across the light), so depth
// stays the perspective's, monotonic along them. A straight edge keeps u affine in 1 / w while v is
// log w: its image bows (edge_sagitta, in closed form), and casters are cut at w = near / 2, where
// v is already below the map's first row.
#include <glm/glm.hpp>

#include "maps/projection_kind.hpp"

namespace shadowlab {

extern const ProjectionKind log_perspective_projection;

// v of the distance w (the 4x4's last row) under the warp; w at or below the clip plane reads as on it.
double log_warp_v(const LogWarp& warp, double w);
// The inverse: the distance w at v, near (far / near)^v.
double log_warp_w(const LogWarp& warp, double v);
// Where the kind cuts casters: this share of near.
inline constexpr double kLogClipShare = 0.5;

}  // namespace shadowlab

#pragma once
/// The solve's moves (move.hpp), one strategy each, in
/// framework/src/solve/moves/. Plans (solve_plans.hpp) put them in order.
#include "hilight/solve/judge.hpp"
#include "hilight/solve/move.hpp"

#include <functional>
#include <memory>

namespace hilight {

/// Seeding (eq. 6), the light hierarchy (eq. 7–8), the cuts refined and the
/// count walked (eq. 9): the fit from nothing. Fills the report's cuts and
/// seeds and the products' hierarchy and cuts.
std::shared_ptr<Move> seed_and_cut_move();
/// The reference's last word (polish_with_reference): `rounds` Gauss–Newton
/// rounds; `keep_count`: no light dropped (fine-tune).
std::shared_ptr<Move> reference_polish_move(bool keep_count, int rounds);
/// Eq. 9 upward: a light more where the fit is worst, while it pays.
std::shared_ptr<Move> add_missing_move();
/// Eq. 9 upward with spots: spots screened from what the lights leave
/// unexplained, joined and polished, kept while they pay (a downlight among lamps).
std::shared_ptr<Move> add_missing_spot_move();
/// Eq. 9 backward: the nearest two point lights merged (eq. 7), while one fewer will do.
std::shared_ptr<Move> merge_pairs_move();
/// The inverse of a merge: the light that owns the worst-explained samples
/// split in two, while the light more pays (up to 4 times).
std::shared_ptr<Move> split_lamps_move();
/// Spotlights from nothing (spot_proposals.hpp), polished by the reference,
/// wide ones tried as point lights; no lights when they leave D̄ at or
/// above `give_up_dbar` (what the point lights reached).
std::shared_ptr<Move> spots_move(double give_up_dbar);
/// Each spot of kWideSpotDeg or more tried as a point light, polished by the reference.
std::shared_ptr<Move> wide_spots_as_points_move();
/// The one trial both the move above and the spot search (settled with its
/// bounce) run: each spot of kWideSpotDeg or more in `fit`, in turn, turned
/// into a point light where it stands and fitted by `refit`; kept (then
/// `kept` is called) when one light fewer will do — the point light is the
/// simpler light, so the cone stays only if it improves D̄ by ε_impro.
Fit wide_spots_as_points(const Judge& judge, Fit fit, const std::function<Fit(const Lighting& trial)>& refit,
                         const std::function<void()>& kept = {});
/// Fine-tune's settling (settle_lights), kept where the reference says it fits better.
std::shared_ptr<Move> settle_move();
/// Each luminaire of the fit turned about its aim to the spin that fits
/// best (luminaire_aim.hpp); the fit's lights are luminaires.
std::shared_ptr<Move> luminaire_aim_move();
/// The worst-explained target points joined to the samples, polished again;
/// sets the report's D̄ over the target.
std::shared_ptr<Move> residual_polish_move(bool keep_count);

} // namespace hilight

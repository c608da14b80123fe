#include "stand/stand_year.hpp"

#include <spdlog/spdlog.h>

namespace heliostand {

StandYear::StandYear(Stand& stand, LightSolver& stand_solver, LightSolver& open_solver, RootZone* roots,
                     YearRecorder* recorder, StandYearSettings settings, StageClock& clock)
    : stand_(stand),
      stand_solver_(stand_solver),
      open_solver_(open_solver),
      roots_(roots),
      recorder_(recorder),
      settings_(settings),
      clock_(clock),
      snapshots_(recorder != nullptr && recorder->draws_trunks()) {}

bool StandYear::is_output_year(int year) const {
  return year == settings_.years || year % settings_.output_interval_years == 0;
}

StandYearResult StandYear::run(int year) {
  StandYearResult result;
  auto record = [&](std::vector<TreeEvent> events) {
    if (recorder_) recorder_->record_events(events);
    result.events.insert(result.events.end(), events.begin(), events.end());
  };
  // 1 grow
  if (year > 0) clock_.time("growth", [&] { stand_.grow_year(); return 0; });
  // 2 light
  result.leaf_balls = stand_.illuminate(stand_solver_, open_solver_, settings_.sky_scale, &clock_);
  spdlog::debug("age {}: {} leaf balls lit", stand_.stand_age(), result.leaf_balls);
  // 3 respond
  if (year > 0) record(clock_.time("light response", [&] { return stand_.respond_to_light(settings_.seed); }));
  // 4 soil
  if (roots_) clock_.time("roots", [&] { year > 0 ? roots_->grow_year(stand_) : roots_->couple(stand_); return 0; });
  // 5 mortality
  if (year > 0) record(clock_.time("mortality", [&] { return stand_.apply_mortality(settings_.seed); }));
  // 6 thinning
  record(stand_.thin());
  // 7 metrics, 8 write
  if (recorder_) clock_.time("output", [&] { write_outputs(year); return 0; });
  // 9 let go: without outputs nothing reads a gone tree again; with them, once an output year has shown it gone.
  stand_.release_gone_crowns([&](const StandTree& tree) {
    return recorder_ == nullptr || snapshots_.written_as_gone(static_cast<std::size_t>(tree.id));
  });
  return result;
}

// An output year's stand table measures its snapshot's trees, so each living stem's volume is computed once a year.
void StandYear::write_outputs(int year) {
  if (!is_output_year(year)) return recorder_->write_stand_rows(take_inventory(stand_, year));
  StandSnapshot snapshot = snapshots_.take(stand_, year);
  if (roots_) roots_->annotate(snapshot);
  recorder_->write_stand_rows(inventory_of(snapshot));
  recorder_->write_year(snapshot);
}

}  // namespace heliostand

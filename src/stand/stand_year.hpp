#pragma once
// The simulated year, owned by one object (as iLand's Model::runYear): its steps, in this order,
//   1 grow       every living tree grows in last year's light (shoots, leader, stem diameter)
//   2 light      the light field of the whole stand, and each crown alone (the open-grown reference)
//   3 respond    new shoots bend toward the light or die of shade; trees without foliage die (cause "light")
//   4 soil       roots grow in the shared soil; the crown–root balance sets next year's branching (optional)
//   5 mortality  suppression and background deaths
//   6 thinning   the thinnings whose age or condition comes due (stand/thinning_trigger.hpp)
//   7 metrics    the living stand's inventory (every year); the snapshot of an output year, which it then measures
//   8 write      stand_table.csv and events.csv (every year); trees.csv and the VTK year (every output year)
//   9 let go     trees that left the stand and have been written for the last time drop their crowns (memory)
// Year 0 is the established stand: steps 2, 4 (balance only), 6, 7, 8 and 9; no growth and no response yet,
// since the established trees grew without neighbours and competition acts from the first simulated year on.
// Data flows one way: each step reads what the steps before it wrote this year.
#include <cstdint>
#include <vector>

#include "core/checkpoint_access.hpp"
#include "light/light_solver.hpp"
#include "records/year_recorder.hpp"
#include "stand/root_zone.hpp"
#include "stand/snapshot.hpp"
#include "stand/stage_clock.hpp"
#include "stand/stand.hpp"

namespace heliostand {

struct StandYearSettings {
  std::uint64_t seed = 1;
  double sky_scale = 1.0;  // the stand's sky relative to the reference sky of the open-grown light
  int years = 0;           // the run's length: its last year is always an output year
  int output_interval_years = 1;
};

struct StandYearResult {
  std::size_t leaf_balls = 0;    // lit in the stand this year
  std::vector<TreeEvent> events;  // deaths (steps 3 and 5) and removals (step 6), in that order
};

class StandYear {
 public:
  // `roots` and `recorder` may be null (no roots; nothing recorded). `clock` times each step.
  StandYear(Stand& stand, LightSolver& stand_solver, LightSolver& open_solver, RootZone* roots,
            YearRecorder* recorder, StandYearSettings settings, StageClock& clock);

  // Runs year `year` of the run (0 = the established stand) through its steps.
  StandYearResult run(int year);
  bool is_output_year(int year) const;

 private:
  friend struct checkpoint::Access;
  void write_outputs(int year);

  Stand& stand_;
  LightSolver& stand_solver_;
  LightSolver& open_solver_;
  RootZone* roots_;
  YearRecorder* recorder_;
  StandYearSettings settings_;
  StageClock& clock_;
  SnapshotTracker snapshots_;
};

}  // namespace heliostand

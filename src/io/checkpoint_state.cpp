#include "io/checkpoint_state.hpp"

#include <fmt/format.h>

#include "io/checkpoint_codec.hpp"
#include "io/checkpoint_file.hpp"
#include "io/stand_output.hpp"
#include "scenario/scenario.hpp"
#include "stand/root_zone.hpp"
#include "stand/stand.hpp"
#include "stand/stand_year.hpp"

namespace heliostand::checkpoint {

using TableLengths = StandOutput::TableLengths;

// Sections are tagged, so that a payload read out of step fails at the next tag instead of restoring garbage.
enum class Section : std::uint32_t { clock = 1, progress, stand, roots, output, snapshots, end };

struct Access {
  // The sizes of the structs written as raw bytes: a build that lays them out otherwise reads no checkpoint of this one.
  static std::string layout() {
    return fmt::format("Shoot {} BranchAxis {} RootSegment {} HollowSpec {} PathBalance {} TreeCalibration {} "
                       "LightBudget {} Production {} TreeStatus {} bool {}",
                       sizeof(Shoot), sizeof(BranchAxis), sizeof(roots::RootSegment), sizeof(hollow::HollowSpec),
                       sizeof(PathBalance), sizeof(TreeCalibration), sizeof(LightBudget),
                       sizeof(StandTableLedger::Production), sizeof(TreeStatus), sizeof(bool));
  }
  static void tag(Writer& out, Section section) { out.raw(section); }
  static void expect(Reader& in, Section section, const char* name) {
    if (in.raw<Section>(name) != section)
      throw CheckpointError(fmt::format("is out of step: the {} section is not where it belongs", name));
  }

  // --- timings and the loop's own counters --------------------------------------------------------------------
  static void save(Writer& out, const StageClock& clock) {
    out.size(clock.stages_.size());
    for (const auto& [name, seconds] : clock.stages_) {
      out.text(name);
      out.raw(seconds);
    }
  }
  static void load(Reader& in, StageClock& clock) {
    clock.stages_.resize(in.size("stage timings", 16));
    for (auto& [name, seconds] : clock.stages_) {
      name = in.text("stage name");
      seconds = in.raw<double>("stage seconds");
    }
  }

  // --- a tree's crown: everything but its species, which the scenario gives --------------------------------------
  static void save(Writer& out, const BranchAxis& axis) {
    out.raw(axis.id);
    out.raw(axis.order);
    out.raw(axis.parent_axis);
    out.raw(axis.first_order_root);
    out.raw(axis.year_formed);
    out.raw(axis.initial_elongation_m);
    out.raw(axis.azimuth_rad);
    out.raw_vector(axis.shoots);
    out.raw(axis.alive);
    out.raw(axis.year_stopped);
    out.raw(axis.length_at_death_m);
    out.raw(axis.starved_years);
  }
  static BranchAxis load_axis(Reader& in) {
    BranchAxis axis;
    in.raw_into(axis.id, "axis id");
    in.raw_into(axis.order, "axis order");
    in.raw_into(axis.parent_axis, "axis parent");
    in.raw_into(axis.first_order_root, "axis first-order root");
    in.raw_into(axis.year_formed, "axis year formed");
    in.raw_into(axis.initial_elongation_m, "axis initial elongation");
    in.raw_into(axis.azimuth_rad, "axis azimuth");
    axis.shoots = in.raw_vector<int>("axis shoots");
    in.raw_into(axis.alive, "axis alive");
    in.raw_into(axis.year_stopped, "axis year stopped");
    in.raw_into(axis.length_at_death_m, "axis length at death");
    in.raw_into(axis.starved_years, "axis starved years");
    return axis;
  }

  static void save(Writer& out, const ConiferTree& tree) {
    out.raw(tree.calibration_);
    out.raw(tree.stem_base_);
    out.raw(tree.seed_);
    out.raw(tree.tree_id_);
    out.raw(tree.age_);
    out.raw(tree.next_axis_id_);
    out.raw(tree.leader_shaded_years_);
    out.raw(tree.height_m_);
    out.raw(tree.dbh_cm_);
    out.raw(tree.crown_base_floor_m_);
    out.raw(tree.light_driven_crown_);
    out.raw(tree.absorbed_light_);
    out.raw(tree.reference_absorbed_light_);
    out.raw(tree.reference_dbh_cm_);
    out.raw_vector(tree.dbh_increments_cm_);
    out.raw_vector(tree.shoots_);
    out.size(tree.axes_.size());
    for (const BranchAxis& axis : tree.axes_) save(out, axis);
    out.raw(tree.branching_bonus_);
  }
  static ConiferTree load_tree(Reader& in, const SpeciesParameters& species) {
    const auto calibration = in.raw<TreeCalibration>("tree calibration");
    const auto stem_base = in.raw<glm::dvec3>("tree stem base");
    const auto seed = in.raw<std::uint64_t>("tree seed");
    const auto id = in.raw<int>("tree id");
    ConiferTree tree(species, calibration, stem_base, seed, id);
    in.raw_into(tree.age_, "tree age");
    in.raw_into(tree.next_axis_id_, "tree next axis id");
    in.raw_into(tree.leader_shaded_years_, "tree leader shaded years");
    in.raw_into(tree.height_m_, "tree height");
    in.raw_into(tree.dbh_cm_, "tree DBH");
    in.raw_into(tree.crown_base_floor_m_, "tree crown base floor");
    in.raw_into(tree.light_driven_crown_, "tree light-driven crown");
    in.raw_into(tree.absorbed_light_, "tree absorbed light");
    in.raw_into(tree.reference_absorbed_light_, "tree reference absorbed light");
    in.raw_into(tree.reference_dbh_cm_, "tree reference DBH");
    tree.dbh_increments_cm_ = in.raw_vector<double>("tree DBH increments");
    tree.shoots_ = in.raw_vector<Shoot>("tree shoots");
    tree.axes_.resize(in.size("tree axes", 8));
    for (BranchAxis& axis : tree.axes_) axis = load_axis(in);
    in.raw_into(tree.branching_bonus_, "tree branching bonus");
    check_crown(tree);
    return tree;
  }
  // Indices that would send the growth rules out of bounds are refused here, not met later as a crash.
  static void check_crown(const ConiferTree& tree) {
    const auto shoots = static_cast<int>(tree.shoots_.size());
    const auto axes = static_cast<int>(tree.axes_.size());
    for (const Shoot& shoot : tree.shoots_)
      if (shoot.parent < -1 || shoot.parent >= shoots || shoot.axis < 0 || shoot.axis >= axes)
        throw CheckpointError(fmt::format("holds a shoot of tree {} that points outside its crown", tree.tree_id_));
    for (const BranchAxis& axis : tree.axes_) {
      bool inside = axis.parent_axis >= -1 && axis.parent_axis < axes && axis.first_order_root >= -1 &&
                    axis.first_order_root < axes;
      for (int shoot : axis.shoots) inside = inside && shoot >= 0 && shoot < shoots;
      if (!inside)
        throw CheckpointError(fmt::format("holds an axis of tree {} that points outside its crown", tree.tree_id_));
    }
  }

  // --- the stand -------------------------------------------------------------------------------------------------
  static void save(Writer& out, const StandTree& tree) {
    out.raw(tree.id);
    out.text(tree.label);
    out.text(tree.species);
    save(out, tree.conifer);
    out.raw(tree.status);
    out.raw(tree.status_changed_at_age);
    out.text(tree.status_reason);
    out.raw_vector(tree.hollows);
    out.raw(tree.light_budget);
  }
  static StandTree load_stand_tree(Reader& in, const Scenario& scenario, std::size_t index) {
    const int id = in.raw<int>("tree index");
    if (id != static_cast<int>(index) || index >= scenario.survey.trees.size())
      throw CheckpointError(fmt::format("holds tree {} where the survey's tree {} belongs", id, index));
    std::string label = in.text("tree label");
    std::string species = in.text("tree species");
    const SurveyRecord& record = scenario.survey.trees[index];
    if (label != record.id || species != record.species)
      throw CheckpointError(fmt::format("holds tree '{}' ({}) where the survey has '{}' ({})", label, species,
                                        record.id, record.species));
    StandTree tree{.id = id, .label = std::move(label), .species = std::move(species),
                   .conifer = load_tree(in, scenario.species_of(record)), .status = TreeStatus::alive,
                   .status_changed_at_age = -1, .status_reason = {}, .hollows = {}, .light_budget = {}};
    in.raw_into(tree.status, "tree status");
    in.raw_into(tree.status_changed_at_age, "tree status age");
    tree.status_reason = in.text("tree status reason");
    tree.hollows = in.raw_vector<hollow::HollowSpec>("tree hollows");
    in.raw_into(tree.light_budget, "tree light budget");
    return tree;
  }

  static void save(Writer& out, const Stand& stand) {
    out.raw(stand.stand_age_);
    out.size(stand.last_fired_age_.size());
    for (const auto& age : stand.last_fired_age_) {
      out.raw(age.has_value());
      out.raw(age.value_or(0));
    }
    out.size(stand.trees_.size());
    for (const StandTree& tree : stand.trees_) save(out, tree);
  }
  static void load(Reader& in, const Scenario& scenario, Stand& stand) {
    in.raw_into(stand.stand_age_, "stand age");
    if (in.size("thinning schedule", 5) != stand.thinning_.size())
      throw CheckpointError("holds another thinning schedule than the scenario's");
    for (auto& age : stand.last_fired_age_) {
      const bool fired = in.raw<bool>("thinning fired");
      const int at = in.raw<int>("thinning fired age");
      age = fired ? std::optional<int>(at) : std::nullopt;
    }
    const std::size_t trees = in.size("trees", 8);
    if (trees != scenario.survey.trees.size())
      throw CheckpointError(fmt::format("holds {} trees; the survey has {}", trees, scenario.survey.trees.size()));
    stand.trees_.clear();
    for (std::size_t i = 0; i < trees; ++i) stand.trees_.push_back(load_stand_tree(in, scenario, i));
  }

  // --- roots and soil --------------------------------------------------------------------------------------------
  static void save(Writer& out, const roots::RootSystem& root) {
    out.raw(root.collar_);
    out.raw(root.year_);
    out.raw(root.next_id_);
    out.raw_vector(root.segments_);
    out.raw(root.branching_bonus_);
  }
  static roots::RootSystem load_root(Reader& in, const StandTree& tree, const roots::RootParameters& parameters) {
    const auto collar = in.raw<glm::dvec3>("root collar");
    roots::RootSystem root(tree.id, collar, parameters, in.raw<int>("root year"));
    in.raw_into(root.next_id_, "root next segment id");
    root.segments_ = in.raw_vector<roots::RootSegment>("root segments");
    const auto count = static_cast<int>(root.segments_.size());
    for (const auto& segment : root.segments_)
      if (segment.parent < -1 || segment.parent >= count)
        throw CheckpointError(fmt::format("holds a root segment of tree {} that points outside its roots", tree.id));
    in.raw_into(root.branching_bonus_, "root branching bonus");
    return root;
  }

  static void save(Writer& out, const RootZone& zone) {
    out.size(zone.roots_.size());
    for (const auto& root : zone.roots_) {
      out.raw(root.has_value());
      if (root) save(out, *root);
    }
    out.size(zone.balance_.size());
    for (const auto& balance : zone.balance_) {
      out.raw(balance.has_value());
      if (balance) out.raw(*balance);
    }
    for (auto field : {roots::SoilField::moisture, roots::SoilField::nutrient}) {
      out.raw_vector(zone.soil_.values(field));
      out.raw_vector(zone.soil_.capacity(field));
    }
  }
  static void load(Reader& in, const Stand& stand, RootZone& zone) {
    const auto& trees = stand.trees();
    if (in.size("root systems", 1) != trees.size()) throw CheckpointError("holds roots for another number of trees");
    zone.roots_.assign(trees.size(), std::nullopt);
    for (std::size_t i = 0; i < trees.size(); ++i)
      if (in.raw<bool>("root system present"))
        zone.roots_[i].emplace(load_root(in, trees[i], zone.settings_.parameters_of(trees[i].species)));
    if (in.size("crown-root balances", 1) != trees.size())
      throw CheckpointError("holds crown-root balances for another number of trees");
    zone.balance_.assign(trees.size(), std::nullopt);
    for (auto& balance : zone.balance_)
      if (in.raw<bool>("balance present")) balance = in.raw<PathBalance>("balance");
    for (auto field : {roots::SoilField::moisture, roots::SoilField::nutrient}) {
      auto values = in.raw_vector<double>("soil values");
      auto capacity = in.raw_vector<double>("soil capacity");
      if (values.size() != zone.soil_.vertex_count() || capacity.size() != zone.soil_.vertex_count())
        throw CheckpointError("holds a soil grid of another size than the scenario's");
      // Capacity has no setter of its own: it is the field's value when it was last filled.
      zone.soil_.values(field) = std::move(capacity);
      zone.soil_.set_capacity_to_current(field);
      zone.soil_.values(field) = std::move(values);
    }
  }

  // --- outputs ---------------------------------------------------------------------------------------------------
  static void save(Writer& out, StandOutput& output) {
    if (!output.events_of_year_.empty())
      throw std::logic_error("a checkpoint is taken between years, when no event waits for its stand table row");
    // The tables' rows so far, by length: a resume cuts their temporaries back to it. They are on the disk before
    // the checkpoint that counts them is (a checkpoint never points past what survives a crash).
    for (auto* table : {output.stand_table_.get(), output.trees_.get(), output.events_.get()}) {
      table->stream.flush();
      sync_file(table->file.temporary_path());
      out.raw(static_cast<std::uint64_t>(std::filesystem::file_size(table->file.temporary_path())));
    }
    out.raw(output.ledger_.stand_);
    out.size(output.ledger_.species_.size());
    for (const auto& [name, production] : output.ledger_.species_) {
      out.text(name);
      out.raw(production);
    }
    const auto& files = output.folder_.output_files();
    out.size(files.size());
    for (const auto& file : files) out.text(file);
    out.raw(output.vtk_ != nullptr);
    if (!output.vtk_) return;
    const auto& entries = output.vtk_->collection_.entries();
    out.size(entries.size());
    for (const auto& entry : entries) {
      out.raw(entry.timestep);
      out.text(entry.file);
    }
    out.text(output.vtk_->sizes_csv_);  // vtk_sizes.csv is rewritten whole every output year
  }
  // Every part is replaced, not added to: after a checkpoint that fails late, an older one can still be loaded.
  static TableLengths load(Reader& in, StandOutput& output) {
    TableLengths lengths{};
    for (auto& length : lengths) length = in.raw<std::uint64_t>("table length");
    in.raw_into(output.ledger_.stand_, "stand production");
    output.ledger_.species_.clear();
    for (std::size_t n = in.size("species production", 16); n > 0; --n) {
      std::string name = in.text("species name");
      output.ledger_.species_[name] = in.raw<StandTableLedger::Production>("species production");
    }
    output.folder_.outputs_.resize(in.size("output files", 8));
    for (auto& file : output.folder_.outputs_) file = in.text("output file");
    if (in.raw<bool>("VTK output") != (output.vtk_ != nullptr))
      throw CheckpointError("was taken with VTK output set otherwise than this run");
    if (output.vtk_) {
      output.vtk_->collection_ = PvdCollection();
      for (std::size_t n = in.size("VTK years", 16); n > 0; --n) {
        const auto timestep = in.raw<double>("VTK year");
        output.vtk_->collection_.add(timestep, in.text("VTK year file"));
      }
      output.vtk_->sizes_csv_ = in.text("VTK sizes table");
    }
    return lengths;
  }

  static void resume_tables(StandOutput& output, const TableLengths& lengths) { output.resume_tables(lengths); }

  static void save(Writer& out, const StandYear& year) { out.bools(year.snapshots_.written_as_gone_); }
  static void load(Reader& in, StandYear& year) { year.snapshots_.written_as_gone_ = in.bools("trees written as gone"); }
};

std::string save_run(const RunParts& run) {
  Writer out;
  Access::tag(out, Section::clock);
  Access::save(out, run.clock);
  Access::tag(out, Section::progress);
  out.raw(static_cast<std::int64_t>(run.progress.tree_years));
  out.raw(run.progress.wall_seconds);
  out.text(run.progress.started_utc);
  out.text(run.progress.command_line);
  Access::tag(out, Section::stand);
  Access::save(out, run.stand);
  Access::tag(out, Section::roots);
  out.raw(run.roots != nullptr);
  if (run.roots) Access::save(out, *run.roots);
  Access::tag(out, Section::output);
  Access::save(out, run.output);
  Access::tag(out, Section::snapshots);
  Access::save(out, run.year);
  Access::tag(out, Section::end);
  return out.bytes();
}

void load_run(std::string_view payload, const Scenario& scenario, const RunParts& run) {
  Reader in(payload);
  Access::expect(in, Section::clock, "stage clock");
  Access::load(in, run.clock);
  Access::expect(in, Section::progress, "progress");
  run.progress.tree_years = static_cast<long>(in.raw<std::int64_t>("tree-years"));
  in.raw_into(run.progress.wall_seconds, "wall seconds");
  run.progress.started_utc = in.text("start time");
  run.progress.command_line = in.text("command line");
  Access::expect(in, Section::stand, "stand");
  Access::load(in, scenario, run.stand);
  Access::expect(in, Section::roots, "roots");
  if (in.raw<bool>("roots present") != (run.roots != nullptr))
    throw CheckpointError("was taken with roots set otherwise than the scenario's");
  if (run.roots) Access::load(in, run.stand, *run.roots);
  Access::expect(in, Section::output, "output");
  const TableLengths tables = Access::load(in, run.output);
  Access::expect(in, Section::snapshots, "snapshots");
  Access::load(in, run.year);
  Access::expect(in, Section::end, "end");
  if (!in.at_end()) throw CheckpointError("has bytes after the end of its run state");
  // Last, once the whole state has been read: the only step that changes a file.
  Access::resume_tables(run.output, tables);
}

std::string layout_fingerprint() { return Access::layout(); }

}  // namespace heliostand::checkpoint

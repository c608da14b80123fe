// Seed 000 (Kanamaru et al. 1991) reproduced: parameter sweeps of the simple dichotomy model, the bud sphere
// and the Fig. 6 scenarios, averaged over seeds, with the paper's findings asserted as the paper states them
// (Figs. 5, 6, 10-14; the table of findings in docs/model.md). Writes
// heliotropism_metrics.md to the output folder and exits 1 when a finding does not hold. Each sweep's trees of the
// first seed go to OUT_DIR/trees (one .vtp of branches and one of tips per tree, listed in trees/index.csv) for
// render_sweeps.py, which draws them side by side like the paper's figure panels.
//   heliotropism_validation validate OUT_DIR [--full] [--only 5,6,10] [--seeds N]   (reduced sizes by default, see
//                                           docs/model.md; --only: these figures alone; --seeds: N seeds per sweep)
//   heliotropism_validation run SCENARIO.toml OUT_DIR    (one stands/kanamaru-* scenario)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "architecture/crown_metrics.hpp"
#include "architecture/kanamaru_growth.hpp"
#include "core/input_error.hpp"
#include "core/seconds_since.hpp"
#include "crown_shape.hpp"
#include "experiments/kanamaru/kanamaru_scenario.hpp"
#include "io/dichotomy_tree_vtk.hpp"
#include "io/log_setup.hpp"
#include "io/output_folder.hpp"

using namespace heliostand;

namespace {

// CI sizes (the paper's in the comments; `--full` uses them).
struct Size {
  int seeds = 2;
  int generations = 20;      // Table 1: 40
  int droop_generations = 26;  // Fig. 10's I sweep: drooping appears after ~24 generations (Table 1: 40)
  int sky_bands = 6;         // 16 x 32 by default
  int regrow_cut = 12, regrow_end = 24;  // Fig. 11: 25 and 60
  int bud_generations = 20;  // Fig. 5: 50
  int bud_latest = 8;        // Fig. 5: 20
  // Fig. 12's "same crown outline" is a claim about grown crowns: a crown with smaller leaf balls comes through
  // the early die-back (when the young crown outgrows R) with a lead of about 5 branch lengths in width, which
  // is 16-22 % of a 20-generation crown but about 12 % at 32 and 9 % at 40 (docs/model.md).
  int outline_generations = 32;  // Table 1: 40
  int outline_seeds = 4;
  int fig6_generations = 20;     // Fig. 6: 50 (stands/kanamaru-fig6-*)
  int fig6_latest = 8;           // sprouting 1..20 in the scenarios

  static Size paper() {
    Size s;
    s.seeds = 5;
    s.generations = s.droop_generations = 40;
    s.sky_bands = 16;
    s.regrow_cut = 25, s.regrow_end = 60;
    s.bud_generations = 50, s.bud_latest = 20;
    s.outline_generations = 40, s.outline_seeds = 5;
    s.fig6_generations = 50, s.fig6_latest = 20;
    return s;
  }
};

KanamaruParameters base(const Size& size) {
  KanamaruParameters p;
  p.generations = size.generations;
  p.light.sky_bands = size.sky_bands;
  p.light.sky_sectors = 2 * size.sky_bands;
  return p;
}

// Mean of the crown metrics over seeds.
struct Averaged {
  CrownMetrics m;
  double survivors_total = 0;
};

CrownMetrics mean_of(const std::vector<CrownMetrics>& all) {
  CrownMetrics m{};
  const double n = static_cast<double>(all.size());
  for (const auto& a : all) {
    m.tips += a.tips;
    m.width += a.width / n;
    m.height += a.height / n;
    m.top += a.top / n;
    m.bottom += a.bottom / n;
    m.drooping += a.drooping / n;
    m.downward += a.downward / n;
    m.nearest_neighbour += a.nearest_neighbour / n;
    m.roundness_cv += a.roundness_cv / n;
    m.quadrat_cv += a.quadrat_cv / n;
    m.crowding += a.crowding / n;
    m.min_x += a.min_x / n;
    m.max_x += a.max_x / n;
  }
  m.tips = static_cast<int>(std::lround(m.tips / n));
  return m;
}

// A living crown stays within a few thousand tips: the largest this validation grows has about 1 400 at CI
// size (Fig. 12, R = 1, 32 generations) and 4 293 at the paper's (Fig. 11's two trees at 60 generations, seed 1;
// docs/model.md), and the largest measured anywhere 6 700 (Fig. 5's bud sphere with I = 0.6 at 20 generations,
// not run here). A model that no longer prunes by light doubles its tips every generation (2^G) and, the light
// costing tips squared, would run for hours: past this budget the validation refuses the crown as a failure (a
// runaway passes it at 16 384 tips, generation 14, within about a minute).
constexpr std::size_t tip_budget = 10000;

struct RunawayCrown : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void grow_within_budget(KanamaruGrowth& growth, DichotomyTree& tree, int generation) {
  growth.grow(tree, generation, [](const DichotomyTree& grown) {
    if (const std::size_t tips = grown.tips().size(); tips > tip_budget)
      throw RunawayCrown(fmt::format("{} living tips at generation {}, over the budget of {} that a living crown "
                                     "never reaches (light pruning has stopped working)",
                                     tips, grown.generation(), tip_budget));
  });
}

DichotomyTree grow_dichotomy(const KanamaruParameters& p, std::uint64_t seed, std::vector<int>* survivors = nullptr,
                             const std::vector<int>* prescribed = nullptr) {
  DichotomyTree tree({root_branch({0.0, 0.0, 0.0}, 15.0)}, p.branching_angle_deg, seed);
  KanamaruGrowth growth(p, seed);
  if (prescribed) growth.random_survivors = *prescribed;
  grow_within_budget(growth, tree, p.generations);
  if (survivors) {
    survivors->assign(1, 0);
    for (const auto& r : growth.history()) survivors->push_back(r.survived);
  }
  return tree;
}

// One tree per sweep value, for the pictures: OUT/trees/NAME.vtp (branches) and NAME_tips.vtp (leaf-ball
// centres), listed in OUT/trees/index.csv (sweep, title, panel label, files) in panel order.
class Gallery {
 public:
  explicit Gallery(std::filesystem::path out) : dir_(std::move(out) / "trees") {
    std::filesystem::create_directories(dir_);
  }
  // Writes the tree and returns its file stem (a tree shared by several sweeps is written once).
  std::string write(const DichotomyTree& tree, double leaf_ball_radius) {
    const std::string stem = fmt::format("tree_{:02d}", written_++);
    write_crown_vtp(tree, leaf_ball_radius, dir_ / (stem + ".vtp"));
    write_tips_vtp(tree, dir_ / (stem + "_tips.vtp"));
    return stem;
  }
  void show(const std::string& sweep, const std::string& title, const std::string& label, const std::string& stem) {
    index_ << fmt::format("{},\"{}\",\"{}\",{}.vtp,{}_tips.vtp\n", sweep, title, label, stem, stem);
  }
  void write_index() const {
    const std::filesystem::path index = dir_ / "index.csv";
    write_whole_file(index, "sweep,title,label,branches,tips\n" + index_.str(), index);
  }

 private:
  std::filesystem::path dir_;
  int written_ = 0;
  std::ostringstream index_;
};

// Sweeps share their base case: remember each parameter set's result.
std::string key_of(const KanamaruParameters& p) {
  return fmt::format("{}|{}|{}|{}|{}|{}|{}|{}|{}", p.generations, p.heliotropism, p.leaf_ball_radius, p.death.standard,
                     p.death.dither, p.light.intensity_ratio, p.light.transmittance, p.light.sky_bands,
                     static_cast<int>(p.pruning));
}

struct SweepPoint {
  CrownMetrics mean;       // over the seeds
  CrownShape shape;        // over the seeds
  std::string first_tree;  // the first seed's tree in the gallery
};

// Mean over seeds 1..seeds; the first seed's tree goes to the gallery.
SweepPoint sweep_point(const KanamaruParameters& p, int seeds, Gallery& gallery) {
  static std::map<std::string, SweepPoint> done;
  const std::string key = fmt::format("{}|{}", key_of(p), seeds);
  if (auto found = done.find(key); found != done.end()) return found->second;
  std::vector<CrownMetrics> all;
  std::vector<CrownShape> shapes;
  SweepPoint point;
  for (int s = 1; s <= seeds; ++s) {
    const DichotomyTree tree = grow_dichotomy(p, static_cast<std::uint64_t>(s));
    all.push_back(measure_crown(crown_tips(tree)));
    shapes.push_back(measure_crown_shape(crown_tips(tree), p.leaf_ball_radius));
    if (s == 1) point.first_tree = gallery.write(tree, p.leaf_ball_radius);
  }
  point.mean = mean_of(all);
  point.shape = mean_of(shapes);
  return done[key] = point;
}

struct Report {
  std::ostringstream table;
  std::ostringstream shapes{"| figure | case | connected | drooping | tip-up of drooping | evenness (Clark-Evans) | "
                            "width / crown depth |\n|---|---|---|---|---|---|---|\n", std::ios::ate};
  std::ostringstream findings;
  int failures = 0;

  Report() {
    table << "| figure | case | tips | width | height | top | bottom | drooping | downward | top-view NN | "
             "roundness CV | quadrat CV | crowding | min x |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  }
  void row(const std::string& figure, const std::string& label, const CrownMetrics& m) {
    table << fmt::format("| {} | {} | {} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.2f} | {:.2f} |\n",
                         figure, label, m.tips, m.width, m.height, m.top, m.bottom, m.drooping, m.downward,
                         m.nearest_neighbour, m.roundness_cv, m.quadrat_cv, m.crowding, m.min_x);
    std::cerr << figure << " " << label << ": tips " << m.tips << " width " << m.width << " height " << m.height
              << " top " << m.top << " bottom " << m.bottom << " droop " << m.drooping << " down " << m.downward << " nn " << m.nearest_neighbour << " cv "
              << m.roundness_cv << " qcv " << m.quadrat_cv << " crowd " << m.crowding << " min_x " << m.min_x << "\n";
  }
  void shape_row(const std::string& figure, const std::string& label, const CrownShape& s) {
    shapes << fmt::format("| {} | {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} |\n", figure, label, s.connected,
                          s.drooping, s.tip_up, s.evenness, s.width_over_depth);
    std::cerr << figure << " " << label << ": connected " << s.connected << " drooping " << s.drooping << " tip-up "
              << s.tip_up << " evenness " << s.evenness << " width/depth " << s.width_over_depth << "\n";
  }
  void check(bool ok, const std::string& finding) {
    findings << "- " << (ok ? "PASS" : "**FAIL**") << " — " << finding << "\n";
    std::cerr << (ok ? "PASS " : "FAIL ") << finding << "\n";
    failures += !ok;
  }
  // A finding of the paper that this model does not reproduce at this size: recorded with its measured values
  // (docs/model.md explains it), never counted as passed; the measured behaviour around it is checked separately.
  void deviation(bool paper_holds, const std::string& finding) {
    findings << "- " << (paper_holds ? "holds here (listed as a deviation in docs/model.md: update it)" : "DEVIATION")
             << " — " << finding << "\n";
    std::cerr << (paper_holds ? "HOLDS (known deviation) " : "DEVIATION ") << finding << "\n";
  }
};

void figure10(const Size& size, Report& report, Gallery& gallery) {
  // (a) random vs (b) light pruning, both without heliotropism, same survivors per generation.
  KanamaruParameters light = base(size);
  light.heliotropism = 0.0;
  KanamaruParameters random = light;
  random.pruning = Pruning::random;
  std::vector<CrownMetrics> by_light, by_chance;
  const std::string title = "Fig. 10: light pruning and heliotropism";
  for (int s = 1; s <= size.seeds; ++s) {
    std::vector<int> survivors;
    const DichotomyTree lit = grow_dichotomy(light, s, &survivors);
    const DichotomyTree chance = grow_dichotomy(random, s, nullptr, &survivors);
    by_light.push_back(measure_crown(crown_tips(lit)));
    by_chance.push_back(measure_crown(crown_tips(chance)));
    if (s == 1) {
      gallery.show("fig10", title, "(a) random pruning, I = 0", gallery.write(chance, random.leaf_ball_radius));
      gallery.show("fig10", title, "(b) light pruning, I = 0", gallery.write(lit, light.leaf_ball_radius));
    }
  }
  const CrownMetrics a = mean_of(by_chance), b = mean_of(by_light);
  report.row("10(a)", "random pruning, I = 0", a);
  report.row("10(b)", "light pruning, I = 0", b);
  report.check(a.tips == b.tips && b.crowding < 0.85 * a.crowding && b.quadrat_cv < a.quadrat_cv,
               fmt::format("Fig. 10: light pruning spreads tips more evenly than random pruning with the same "
                           "survivors (top view: tips within 2R {:.2f} vs {:.2f}, > 15 % fewer; quadrat CV "
                           "{:.3f} < {:.3f})", b.crowding, a.crowding, b.quadrat_cv, a.quadrat_cv));
  std::vector<CrownMetrics> by_strength;
  std::vector<CrownShape> shape;
  char panel = 'c';
  for (double strength : {0.0, 0.2, 0.4}) {
    KanamaruParameters p = base(size);
    p.generations = size.droop_generations;
    p.heliotropism = strength;
    const SweepPoint point = sweep_point(p, size.seeds, gallery);
    by_strength.push_back(point.mean);
    shape.push_back(point.shape);
    gallery.show("fig10", title, fmt::format("({}) I = {:.1f}, G = {}", panel++, strength, size.droop_generations),
                 point.first_tree);
    const std::string label = fmt::format("I = {:.1f}, G = {}", strength, size.droop_generations);
    report.row("10(c-e)", label, by_strength.back());
    report.shape_row("10(c-e)", label, shape.back());
  }
  report.check(by_strength[0].tips < by_strength[1].tips && by_strength[1].tips < by_strength[2].tips,
               fmt::format("Fig. 10: increasing I increases surviving tips ({} < {} < {})", by_strength[0].tips,
                           by_strength[1].tips, by_strength[2].tips));
  // The paper's weeping: lower boughs droop below their base while their tips turn up.
  report.check(shape[0].drooping < shape[1].drooping && shape[1].drooping < shape[2].drooping &&
                   shape[2].drooping > 0.02,
               fmt::format("Fig. 10: increasing I produces drooping boughs (tips below their bough's base {:.3f} < "
                           "{:.3f} < {:.3f}, > 2 % at I = 0.4)", shape[0].drooping, shape[1].drooping,
                           shape[2].drooping));
  report.deviation(shape[2].tip_up > 0.5,
                   fmt::format("Fig. 10: the drooping boughs' tips turn up (of the drooping tips, pointing above the "
                               "horizontal: I = 0.2 {:.3f}, I = 0.4 {:.3f}; paper: most)", shape[1].tip_up,
                               shape[2].tip_up));
  report.check(shape[0].evenness < shape[2].evenness,
               fmt::format("Fig. 10: heliotropism spreads the tips more evenly in top view (Clark-Evans index "
                           "I = 0.4 {:.3f} > I = 0 {:.3f})", shape[2].evenness, shape[0].evenness));
  report.deviation(shape[0].evenness < shape[1].evenness && shape[1].evenness < shape[2].evenness,
                   fmt::format("Fig. 10: evenness rises steadily with I (Clark-Evans index I = 0, 0.2, 0.4: {:.3f}, "
                               "{:.3f}, {:.3f})", shape[0].evenness, shape[1].evenness, shape[2].evenness));
}

void figure11(const Size& size, Report& report, Gallery& gallery) {
  const std::string title = "Fig. 11: crown regeneration (left tree cut)";
  std::vector<CrownMetrics> kept, cut;
  std::vector<CrownShape> shared_at_cut, shared_at_end;
  std::vector<double> overlap_at_cut, overlap_at_end;  // left tree's rightmost tip − right tree's leftmost tip
  for (int s = 1; s <= size.seeds; ++s) {
    for (bool remove : {false, true}) {
      KanamaruParameters p = base(size);
      DichotomyTree tree({root_branch({-3.0, 0.0, 0.0}, 15.0, 0), root_branch({3.0, 0.0, 0.0}, 15.0, 1)},
                         p.branching_angle_deg, s);
      KanamaruGrowth growth(p, s);
      grow_within_budget(growth, tree, size.regrow_cut);
      auto record_shared = [&](std::vector<CrownShape>& shape, std::vector<double>& overlap) {
        shape.push_back(measure_crown_shape(crown_tips(tree), p.leaf_ball_radius));
        overlap.push_back(measure_crown(crown_tips(tree, 0)).max_x - measure_crown(crown_tips(tree, 1)).min_x);
      };
      if (!remove) record_shared(shared_at_cut, overlap_at_cut);
      if (s == 1 && !remove)
        gallery.show("fig11", title, fmt::format("(a) generation {}", size.regrow_cut), gallery.write(tree, p.leaf_ball_radius));
      if (remove) tree.remove_group(0);
      grow_within_budget(growth, tree, size.regrow_end);
      if (!remove) record_shared(shared_at_end, overlap_at_end);
      if (s == 1)
        gallery.show("fig11", title,
                     remove ? fmt::format("(c) left cut after {}, generation {}", size.regrow_cut, size.regrow_end)
                            : fmt::format("(b) generation {}", size.regrow_end),
                     gallery.write(tree, p.leaf_ball_radius));
      CrownMetrics right = measure_crown(crown_tips(tree, 1));
      right.min_x -= 3.0;  // relative to the right tree's stem
      right.max_x -= 3.0;
      (remove ? cut : kept).push_back(right);
    }
  }
  const CrownMetrics k = mean_of(kept), c = mean_of(cut);
  auto mean = [](const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v) m += x / v.size();
    return m;
  };
  const CrownShape at_cut = mean_of(shared_at_cut), together = mean_of(shared_at_end);
  const double overlap_cut = mean(overlap_at_cut), mean_overlap = mean(overlap_at_end);
  report.shape_row("11", fmt::format("both trees, gen {}", size.regrow_cut), at_cut);
  report.shape_row("11", fmt::format("both trees, gen {}", size.regrow_end), together);
  report.row("11", fmt::format("right tree, left kept (gen {})", size.regrow_end), k);
  report.row("11", fmt::format("right tree, left cut after gen {}", size.regrow_cut), c);
  report.check(mean_overlap > 0.0,
               fmt::format("Fig. 11: the two trees share one crown by generation {}: their crowns overlap (the left "
                           "tree's rightmost tip {:.2f} branch lengths past the right tree's leftmost)",
                           size.regrow_end, mean_overlap));
  report.deviation(together.connected > 0.95,
                   fmt::format("Fig. 11: the shared crown is one crown, > 95 % of the tips chained by gaps < 4R "
                               "(generation {}: {:.3f}; at the cut, generation {}: {:.3f})", size.regrow_end,
                               together.connected, size.regrow_cut, at_cut.connected));
  report.deviation(at_cut.connected > 0.95 && overlap_cut > 0.0,
                   fmt::format("Fig. 11: the crowns are already one when the left tree is cut (generation {}: tips "
                               "in one crown {:.3f}, overlap {:.2f})", size.regrow_cut, at_cut.connected, overlap_cut));
  report.check(c.min_x < k.min_x - 1.0,
               fmt::format("Fig. 11: with the left tree cut the right crown reaches further left ({:.2f} vs {:.2f} "
                           "from its stem, by more than one branch length)", c.min_x, k.min_x));
}

void figure12(const Size& size, Report& report, Gallery& gallery) {
  std::vector<CrownMetrics> m;
  char panel = 'a';
  for (double radius : {2.0, 1.5, 1.0}) {
    KanamaruParameters p = base(size);
    p.leaf_ball_radius = radius;
    const SweepPoint point = sweep_point(p, size.seeds, gallery);
    m.push_back(point.mean);
    gallery.show("fig12", "Fig. 12: leaf-ball radius R", fmt::format("({}) R = {:g}, G = {}", panel++, radius, size.generations),
                 point.first_tree);
    report.row("12", fmt::format("R = {:g}", radius), m.back());
  }
  report.check(m[2].tips > m[1].tips && m[1].tips > m[0].tips,
               fmt::format("Fig. 12: smaller R keeps more branches (R = 1: {} > R = 1.5: {} > R = 2: {})", m[2].tips,
                           m[1].tips, m[0].tips));
  // The outline on grown crowns (Size::outline_generations, more seeds: the R = 2 crowns vary most), measured on
  // the crown alone: width over crown depth, without the 15-branch-length bare stem below it.
  std::vector<CrownMetrics> grown;
  std::vector<CrownShape> outline;
  for (double radius : {2.0, 1.5, 1.0}) {
    KanamaruParameters p = base(size);
    p.generations = size.outline_generations;
    p.leaf_ball_radius = radius;
    const SweepPoint point = sweep_point(p, size.outline_seeds, gallery);
    grown.push_back(point.mean);
    outline.push_back(point.shape);
    if (size.outline_generations != size.generations)  // else these trees are already in the picture
      gallery.show("fig12", "Fig. 12: leaf-ball radius R",
                   fmt::format("({}) R = {:g}, G = {}", panel++, radius, size.outline_generations), point.first_tree);
    const std::string label = fmt::format("R = {:g}, G = {}, {} seeds", radius, size.outline_generations, size.outline_seeds);
    report.row("12", label, grown.back());
    report.shape_row("12", label, outline.back());
  }
  auto change = [&](int i) { return outline[i].width_over_depth / outline[0].width_over_depth - 1.0; };
  auto with_stem = [&](int i) { return grown[i].width / grown[i].top; };
  report.check(std::abs(change(1)) < 0.15,
               fmt::format("Fig. 12: same crown outline (width / crown depth, without the bare stem) within 15 % "
                           "between R = 1.5 and R = 2 at G = {}: {:.3f} vs {:.3f}, {:+.0f} % (width / tree height "
                           "with the stem: {:.3f} vs {:.3f})", size.outline_generations, outline[1].width_over_depth,
                           outline[0].width_over_depth, 100.0 * change(1), with_stem(1), with_stem(0)));
  report.deviation(std::abs(change(2)) < 0.15,
                   fmt::format("Fig. 12: same crown outline for R = 1 (width / crown depth {:.3f} vs R = 2's {:.3f}, "
                               "{:+.0f} %; with the stem {:.3f} vs {:.3f})", outline[2].width_over_depth,
                               outline[0].width_over_depth, 100.0 * change(2), with_stem(2), with_stem(0)));
}

void figure13(const Size& size, Report& report, Gallery& gallery) {
  KanamaruParameters high = base(size), low = base(size);
  low.death.standard = 0.5;
  const SweepPoint at_high = sweep_point(high, size.seeds, gallery), at_low = sweep_point(low, size.seeds, gallery);
  gallery.show("fig13", "Fig. 13: standard death threshold D0", "(a) D0 = 0.6", at_high.first_tree);
  gallery.show("fig13", "Fig. 13: standard death threshold D0", "(b) D0 = 0.5", at_low.first_tree);
  const CrownMetrics a = at_high.mean, b = at_low.mean;
  report.row("13", "D0 = 0.6", a);
  report.row("13", "D0 = 0.5", b);
  report.check(b.tips > a.tips, fmt::format("Fig. 13: smaller D0 keeps more branches ({} > {})", b.tips, a.tips));
  report.check(b.width > a.width && b.bottom < a.bottom,
               fmt::format("Fig. 13: smaller D0 gives a wider, lower crown (width {:.2f} > {:.2f}, lowest tip "
                           "{:.2f} < {:.2f})", b.width, a.width, b.bottom, a.bottom));
}

void figure14(const Size& size, Report& report, Gallery& gallery) {
  std::vector<CrownMetrics> m;
  char panel = 'a';
  for (double ratio : {1.0, 1.5, 3.0}) {
    KanamaruParameters p = base(size);
    p.light.intensity_ratio = ratio;
    const SweepPoint point = sweep_point(p, size.seeds, gallery);
    m.push_back(point.mean);
    gallery.show("fig14", "Fig. 14: light intensity ratio L", fmt::format("({}) L = {:g}", panel++, ratio), point.first_tree);
    report.row("14", fmt::format("L = {:g}", ratio), m.back());
  }
  report.check(m[0].downward > m[1].downward,
               fmt::format("Fig. 14: smaller L gives more downward tips ({:.3f} > {:.3f})", m[0].downward, m[1].downward));
  report.check(m[2].width < m[1].width,
               fmt::format("Fig. 14: larger L gives a narrower crown (width {:.2f} < {:.2f})", m[2].width, m[1].width));
  report.check(m[2].top > m[1].top,
               fmt::format("Fig. 14: larger L gives a taller tree (highest tip {:.2f} > {:.2f}; crown depth {:.2f} vs "
                           "{:.2f})", m[2].top, m[1].top, m[2].height, m[1].height));
}

// A crown grown from scattered buds (Figs. 5 and 6): the starts come from `starts`, one set per seed.
struct BudCrown {
  CrownMetrics metrics;
  CrownShape shape;
};

BudCrown grow_from_buds(const KanamaruParameters& p, const std::vector<BudStart>& starts, std::uint64_t seed,
                        Gallery* gallery, const std::string& sweep, const std::string& title, const std::string& label) {
  DichotomyTree tree(starts, p.branching_angle_deg, seed);
  KanamaruGrowth growth(p, seed);
  grow_within_budget(growth, tree, p.generations);
  if (gallery) gallery->show(sweep, title, label, gallery->write(tree, p.leaf_ball_radius));
  return {measure_crown(crown_tips(tree)), measure_crown_shape(crown_tips(tree), p.leaf_ball_radius)};
}

// Means over seeds of the bud crowns grown with heliotropism `strength`; the first seed's tree goes to the gallery.
template <typename Starts>
BudCrown bud_crowns(KanamaruParameters p, double strength, int seeds, const Starts& starts_for_seed, Gallery& gallery,
                    const std::string& sweep, const std::string& title, const std::string& label) {
  p.heliotropism = strength;
  std::vector<CrownMetrics> metrics;
  std::vector<CrownShape> shapes;
  for (int s = 1; s <= seeds; ++s) {
    const BudCrown crown = grow_from_buds(p, starts_for_seed(s), s, s == 1 ? &gallery : nullptr, sweep, title, label);
    metrics.push_back(crown.metrics);
    shapes.push_back(crown.shape);
  }
  return {mean_of(metrics), mean_of(shapes)};
}

void figure5(const Size& size, Report& report, Gallery& gallery) {
  KanamaruParameters p = base(size);
  p.generations = size.bud_generations;
  auto starts = [&](int s) { return bud_sphere({{0.0, 0.0, 5.0}, 5.0, 50, size.bud_latest}, s); };
  std::vector<BudCrown> by_strength;
  // (a) I = 0, then (b), (c) stronger (the seed gives no values): up to Table 1's 0.4. I = 0.6 overgrows at
  // these sizes (about 6 700 tips at 20 generations, minutes per tree).
  const std::vector<double> strengths{0.0, 0.2, 0.4};
  char panel = 'a';
  for (double strength : strengths) {
    const std::string label = fmt::format("({}) I = {:g}", panel++, strength);
    by_strength.push_back(bud_crowns(p, strength, size.seeds, starts, gallery, "fig05",
                                     "Fig. 5: crown formation from a bud sphere", label));
    report.row("5", fmt::format("bud sphere, I = {:g}", strength), by_strength.back().metrics);
    report.shape_row("5", fmt::format("bud sphere, I = {:g}", strength), by_strength.back().shape);
  }
  report.check(by_strength[2].metrics.roundness_cv < by_strength[0].metrics.roundness_cv,
               fmt::format("Fig. 5: heliotropism makes the bud-sphere crown rounder (CV of tip distance from the "
                           "centroid, I = 0.4 {:.3f} < I = 0 {:.3f})", by_strength[2].metrics.roundness_cv,
                           by_strength[0].metrics.roundness_cv));
  bool rounder = true;
  std::string cvs = fmt::format("{:.3f}", by_strength[0].metrics.roundness_cv);
  for (std::size_t i = 1; i < by_strength.size(); ++i) {
    rounder = rounder && by_strength[i].metrics.roundness_cv < by_strength[i - 1].metrics.roundness_cv;
    cvs += fmt::format(" > {:.3f}", by_strength[i].metrics.roundness_cv);
  }
  report.deviation(rounder, fmt::format("Fig. 5: stronger heliotropism, steadily rounder bud-sphere crown (CV of "
                                        "tip distance from the centroid, I = 0, 0.2, 0.4: {})", cvs));
  const CrownShape& table1 = by_strength[2].shape;
  report.check(table1.connected > by_strength[0].shape.connected,
               fmt::format("Fig. 5: heliotropism gathers the buds' branches into a crown (tips chained by gaps < 4R "
                           "in the largest group: I = 0.4 {:.3f} > I = 0 {:.3f})", table1.connected,
                           by_strength[0].shape.connected));
  report.deviation(table1.connected > 0.95,
                   fmt::format("Fig. 5: one crown, > 95 % of the tips chained by gaps < 4R (I = 0.4: {:.3f})",
                               table1.connected));
}

// Fig. 6: clusters of buds, or buds on a pruned trunk's surface, still form one round crown. The scenarios of
// stands/kanamaru-fig6-* at CI size: fewer generations and an earlier sprouting, as for Fig. 5.
void figure6(const Size& size, Report& report, Gallery& gallery) {
  for (const std::string layout : {"clusters", "cylinder"}) {
    KanamaruScenario scenario = load_kanamaru_scenario(
        std::filesystem::path(HELIOSTAND_SOURCE_DIR) / "stands" / ("kanamaru-fig6-" + layout) / "scenario.toml");
    scenario.latest_sprouting = size.fig6_latest;
    KanamaruParameters p = scenario.parameters;
    p.generations = size.fig6_generations;
    p.light.sky_bands = size.sky_bands;
    p.light.sky_sectors = 2 * size.sky_bands;
    auto starts = [&](int s) {
      KanamaruScenario seeded = scenario;
      seeded.seed = static_cast<std::uint64_t>(s);
      return starts_of(seeded);
    };
    const std::string title = "Fig. 6: buds in " + layout;
    const BudCrown without = bud_crowns(p, 0.0, size.seeds, starts, gallery, "fig06", title, layout + ", I = 0");
    const BudCrown with = bud_crowns(p, scenario.parameters.heliotropism, size.seeds, starts, gallery, "fig06", title,
                                     fmt::format("{}, I = {:g}", layout, scenario.parameters.heliotropism));
    for (const auto& [label, crown] : {std::pair{"I = 0", without}, std::pair{"with I", with}}) {
      report.row("6", layout + ", " + label, crown.metrics);
      report.shape_row("6", layout + ", " + label, crown.shape);
    }
    report.check(with.shape.connected > without.shape.connected,
                 fmt::format("Fig. 6: heliotropism gathers the branches of buds in {} into a crown (tips chained by "
                             "gaps < 4R in the largest group: I = {:g} {:.3f} > I = 0 {:.3f})", layout,
                             scenario.parameters.heliotropism, with.shape.connected, without.shape.connected));
    report.deviation(with.shape.connected > 0.95,
                     fmt::format("Fig. 6: buds in {} form one crown, > 95 % of the tips chained by gaps < 4R ({:.3f})",
                                 layout, with.shape.connected));
    const std::string rounder = fmt::format("Fig. 6: buds in {} form a rounder crown with heliotropism than without "
                                            "(roundness CV {:.3f} < {:.3f})", layout, with.metrics.roundness_cv,
                                            without.metrics.roundness_cv);
    // Buds on a cylinder without heliotropism already radiate into a shell around the trunk (round by this
    // measure); docs/model.md.
    if (layout == "clusters") report.check(with.metrics.roundness_cv < without.metrics.roundness_cv, rounder);
    else report.deviation(with.metrics.roundness_cv < without.metrics.roundness_cv, rounder);
  }
}

// `only`: figure numbers to run ("5,6,10"), empty for all (the mutation harness runs the figures a break touches).
// `seeds`: when > 0, the seeds of every sweep (a paper-size figure too slow with 5 seeds on 2 cores; docs/model.md).
int validate(const std::string& out, bool full, const std::string& only, int seeds) {
  Size size;
  if (full) size = Size::paper();
  if (seeds > 0) size.seeds = size.outline_seeds = seeds;
  Report report;
  Gallery gallery(out);
  const std::vector<std::pair<int, void (*)(const Size&, Report&, Gallery&)>> figures{
      {10, figure10}, {11, figure11}, {12, figure12}, {13, figure13}, {14, figure14}, {5, figure5}, {6, figure6}};
  for (const auto& [number, figure] : figures) {
    if (!only.empty() && ("," + only + ",").find("," + std::to_string(number) + ",") == std::string::npos) continue;
    const auto start = std::chrono::steady_clock::now();
    try {
      figure(size, report, gallery);
    } catch (const RunawayCrown& runaway) {
      report.check(false, fmt::format("Fig. {}: a crown ran away, the figure was stopped: {}", number, runaway.what()));
    }
    std::cerr << "  (" << seconds_since(start) << " s)\n";
  }
  gallery.write_index();
  std::ostringstream md;
  md << "# Seed 000 findings (heliotropism validation)\n\n"
     << fmt::format("Sizes: {} seeds, {} generations (Table 1: 40; Fig. 10's I sweep {}), sky {} x {}, Fig. 11 cut after {} grown to {}, "
                    "Fig. 5 {} generations with sprouting 1..{}; Fig. 12's outline at {} generations, {} seeds; Fig. 6 {} generations with sprouting 1..{}; transmittance t = {:g}. Lengths in branch lengths.\n\n",
                    size.seeds, size.generations, size.droop_generations, size.sky_bands, 2 * size.sky_bands, size.regrow_cut,
                    size.regrow_end, size.bud_generations, size.bud_latest, size.outline_generations, size.outline_seeds, size.fig6_generations, size.fig6_latest, base(size).light.transmittance)
     << report.table.str() << "\n" << report.shapes.str() << "\n## Findings\n\n" << report.findings.str();
  md << "\nColumns: lengths in branch lengths; drooping = tips below their bough's base (10 generations back); "
        "downward = tips pointing below the horizontal; top-view NN = mean nearest-neighbour distance; roundness CV = "
        "coefficient of variation of tip distances from their centroid; quadrat CV over 4R cells; crowding = mean "
        "number of tips within 2R (top view); min x = leftmost tip (Fig. 11: from the right tree's stem). Second "
        "table (crown_shape.hpp): connected = fraction of the tips in the largest group of touching leaf balls "
        "(centres closer than 2R); tip-up = drooping tips whose branch points above the horizontal, as a fraction "
        "of the drooping ones; evenness = Clark-Evans index of the tips in top view (1 random, > 1 even); width / "
        "crown depth = the outline without the bare stem.\n";
  const std::filesystem::path metrics = std::filesystem::path(out) / "heliotropism_metrics.md";
  write_whole_file(metrics, md.str(), metrics);  // checked: a report that could not be written is an error
  std::cerr << report.failures << " finding(s) failed; table in " << out << "/heliotropism_metrics.md\n";
  return report.failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  heliostand::log_to_stderr(spdlog::level::info);  // VTK's errors as log lines, as heliostand prints them
  if (argc >= 3 && std::strcmp(argv[1], "validate") == 0) {
    bool full = false;
    std::string only;
    int seeds = 0;
    for (int i = 3; i < argc; ++i) {
      if (std::strcmp(argv[i], "--full") == 0) full = true;
      else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc) only = argv[++i];
      else if (std::strcmp(argv[i], "--seeds") == 0 && i + 1 < argc && std::atoi(argv[i + 1]) > 0) seeds = std::atoi(argv[++i]);
      else {
        std::cerr << "heliotropism_validation validate: unknown option " << argv[i] << "\n";
        return 2;
      }
    }
    try {
      return validate(argv[2], full, only, seeds);
    } catch (const std::exception& e) {  // e.g. a report or tree file that could not be written: never a silent 0
      std::cerr << "error: " << e.what() << "\n";
      return 2;
    }
  }
  if (argc == 4 && std::strcmp(argv[1], "run") == 0) {
    try {
      const KanamaruScenario scenario = load_kanamaru_scenario(argv[2]);
      // The CTest reruns it into the same build folder: replace the earlier run there (never another folder).
      const KanamaruRunSummary s = run_kanamaru(scenario, argv[3], /*force=*/true);
      std::cout << fmt::format("{}: {} generations, {} living tips, {} living branches, {:.1f} s -> {}\n", argv[2],
                               s.generations, s.tips, s.living_branches, s.seconds, argv[3]);
      return 0;
    } catch (const InputError& e) {
      for (const auto& problem : e.problems()) std::cerr << problem.format(e.field_kind()) << "\n";
      return 2;
    } catch (const std::exception& e) {  // an output folder refused or a file that could not be written
      std::cerr << "error: " << e.what() << "\n";
      return 1;
    }
  }
  std::cerr << "usage: heliotropism_validation validate OUT_DIR [--full] [--only 5,6,10] [--seeds N] | run SCENARIO.toml OUT_DIR\n";
  return 2;
}

// The technique registry and its first new rows, ESM with failure classification (seed 002 §3.3).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <vector>

#include "basis/basis.h"
#include "techniques/lp_options.h"
#include "techniques/lp_technique.h"
#include "techniques/registry.h"
#include "util/config.h"
#include "util/error.h"

namespace mb {
namespace {

TEST(TechniqueRegistry, EveryRowMakesATechniqueOfItsOwnName) {
  const TechniqueParams params;
  std::set<std::string> names;
  for (const TechniqueRow* row : family_rows(TechniqueFamily::HardShadow)) {
    EXPECT_TRUE(names.insert(row->name).second) << row->name << " is registered twice";
    // A family row's example (lp_stored:hamburger4_16bit), or the family with power4 (lp:power4).
    const std::string name = !row->prefix()         ? row->name
                             : row->example.empty() ? row->name + "power4"
                                                    : row->example;
    EXPECT_EQ(make_technique(name, params)->name(), name);
    EXPECT_EQ(find_technique(name, TechniqueFamily::HardShadow), row);
  }
  EXPECT_EQ(find_technique("esm_zmx"), nullptr);
  EXPECT_THROW(make_technique("esm_zmx", params), InputError);
}

// One table for every family: rows sorted by family and rank, each with exactly its family's
// factory, names unique within a family (lp:<basis> is a row of two), and a name of one family is
// refused by another's factory with the family it belongs to.
TEST(TechniqueRegistry, EveryFamilyIsOneTableOfRows) {
  const auto& rows = technique_registry();
  std::set<std::pair<TechniqueFamily, std::string>> names;
  for (size_t i = 0; i < rows.size(); ++i) {
    const TechniqueRow& row = rows[i];
    EXPECT_TRUE(names.insert({row.family, row.name}).second) << row.name;
    if (i > 0) {
      EXPECT_LE(std::pair(rows[i - 1].family, rows[i - 1].rank), std::pair(row.family, row.rank))
          << row.name;
    }
    const int factories = (row.make != nullptr) + (row.make_soft != nullptr) +
                          (row.make_oit != nullptr) + (row.make_scatter != nullptr);
    EXPECT_EQ(factories, 1) << row.name;
    EXPECT_EQ(row.make != nullptr, row.family == TechniqueFamily::HardShadow) << row.name;
    EXPECT_EQ(row.make_soft != nullptr, row.family == TechniqueFamily::SoftShadow) << row.name;
    EXPECT_EQ(row.make_oit != nullptr, row.family == TechniqueFamily::Transmittance) << row.name;
    EXPECT_EQ(row.make_scatter != nullptr, row.family == TechniqueFamily::Scattering) << row.name;
    EXPECT_FALSE(row.summary.empty()) << row.name;
    EXPECT_FALSE(row.bound.empty()) << row.name;
    if (row.prefix() && row.default_run) {
      EXPECT_FALSE(row.example.empty()) << row.name;
    }
  }
  for (TechniqueFamily family : {TechniqueFamily::HardShadow, TechniqueFamily::SoftShadow,
                                 TechniqueFamily::Transmittance, TechniqueFamily::Scattering})
    EXPECT_FALSE(family_rows(family).empty()) << family_title(family);
  EXPECT_EQ(find_technique("lp:power4", TechniqueFamily::Transmittance)->family,
            TechniqueFamily::Transmittance);
  EXPECT_EQ(find_technique("lp:power4", TechniqueFamily::HardShadow)->family,
            TechniqueFamily::HardShadow);
  // The longest prefix wins: msm_soft:lp:<basis> is not msm_soft.
  EXPECT_TRUE(find_technique("msm_soft:lp:power4")->prefix());
  try {
    make_technique(family_rows(TechniqueFamily::SoftShadow).front()->name, TechniqueParams());
    ADD_FAILURE() << "a soft row made a hard-shadow technique";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("soft shadows"), std::string::npos) << e.what();
  }
  // The list `options techniques` prints: a section per family, every row in it.
  const std::string table = technique_table_markdown();
  for (const TechniqueRow& row : rows)
    EXPECT_NE(table.find("| `" + row.display_name() + "` |"), std::string::npos) << row.name;
  EXPECT_LT(table.find("Hard shadows:"), table.find("Soft shadows:"));
  EXPECT_LT(table.find("Soft shadows:"), table.find("Transmittance:"));
}

// Defaults are written once, in the option records: a default-made TechniqueParams holds each
// record's default, parsed here from the record's own text, and the lp.* records' for its LP.
TEST(TechniqueRegistry, DefaultParametersAreTheRecordsDefaults) {
  const TechniqueParams params;
  // Every family's rows declare options of their own (pcss_csm's terms, MBOIT's beta, ray
  // marching's seed), each held with its record's default.
  EXPECT_GE(technique_option_specs({TechniqueFamily::SoftShadow}).size(), 8u);
  EXPECT_GE(technique_option_specs({TechniqueFamily::Transmittance}).size(), 1u);
  EXPECT_GE(technique_option_specs({TechniqueFamily::Scattering}).size(), 1u);
  const std::vector<OptionSpec> specs =
      technique_option_specs({TechniqueFamily::HardShadow, TechniqueFamily::SoftShadow,
                              TechniqueFamily::Transmittance, TechniqueFamily::Scattering});
  ASSERT_GT(specs.size(), 25u);
  for (const OptionSpec& spec : specs) {
    const double expected = YAML::Load(spec.default_value).as<double>();
    if (spec.type == OptionType::Integer) {
      EXPECT_EQ(params.integer(spec.name), expected) << spec.name;
    } else {
      ASSERT_EQ(spec.type, OptionType::Number) << spec.name;
      EXPECT_EQ(params.number(spec.name), expected) << spec.name;
    }
  }
  const Config lp(lp_option_specs());
  EXPECT_EQ(params.lp.grid, lp.integer("lp.grid"));
  EXPECT_EQ(params.lp.lo, lp.number("lp.lo"));
  EXPECT_EQ(params.lp.hi, lp.number("lp.hi"));
  EXPECT_EQ(params.lp.quantize, lp.boolean("lp.quantize"));
  EXPECT_EQ(params.lp.continuous, lp.string("lp.discretization") == "continuous");
  EXPECT_EQ(params.lp_backend, lp.string("lp.backend"));
  EXPECT_EQ(params.lp_moment_box, lp.string("lp.moment_box"));
  EXPECT_EQ(params.lp_beta, lp.number("lp.beta"));
  EXPECT_EQ(default_techniques(TechniqueFamily::Transmittance).back(), ']');
}

// A key no row declares, or read as the wrong type, is a programming error, not a value.
TEST(TechniqueRegistry, AnUnknownOrMistypedKeyIsAnError) {
  TechniqueParams params;
  EXPECT_THROW(params.number("esm.k"), std::logic_error);
  EXPECT_THROW(params.integer("esm.k"), std::logic_error);
  EXPECT_THROW(params.set("esm.k", 1), std::logic_error);
  EXPECT_THROW(params.integer("esm.c"), std::logic_error);     // a number
  EXPECT_THROW(params.number("csm.terms"), std::logic_error);  // an integer
  EXPECT_THROW(params.set("csm.terms", 2.5), std::logic_error);
  EXPECT_NO_THROW(params.set("csm.terms", 2));
  EXPECT_EQ(params.integer("csm.terms"), 2);
}

// An option set in a config reaches the technique that declares it: esm.c = 20 makes ESM's map
// exp(20 z) and its bound Markov's for that exponent.
TEST(TechniqueRegistry, AConfigValueReachesItsTechnique) {
  Config config(technique_option_specs({TechniqueFamily::HardShadow}));
  config.set("esm.c=20");
  TechniqueParams params;
  read_technique_options(config, params);
  EXPECT_EQ(params.number("esm.c"), 20);
  const auto set = make_technique("esm", params);
  const auto plain = make_technique("esm", TechniqueParams());
  EXPECT_EQ(set->basis().names(), Basis::parse({"exp(20*z)"}).names());
  // Atoms of mass 1/2 at 0.2 and 0.45, received at 0.5: Markov's bound on exp(c z) for each c,
  // 0.815 at c = 20 and 0.991 at the default 80.
  std::vector<double> answers;
  for (const auto& [technique, c] :
       {std::pair{set.get(), 20.0}, std::pair{plain.get(), TechniqueParams().number("esm.c")}}) {
    const double moment = 0.5 * std::exp(c * 0.2) + 0.5 * std::exp(c * 0.45);
    FragmentInput in;
    in.moments = {&moment, 1};
    in.zf = 0.5;
    answers.push_back(technique->shadow(in));
    EXPECT_NEAR(answers.back(), 1 - 0.5 * std::exp(-0.3 * c) - 0.5 * std::exp(-0.05 * c), 1e-12)
        << c;
  }
  EXPECT_LT(answers[0], answers[1] - 0.1);
}

// verify's LP for a row reads the same number of channels as the technique's map: the LP answers
// Problem 1 for the information the technique has (docs/reference.md §6).
TEST(TechniqueRegistry, VerifyRecipesSpanTheTechniquesOwnChannels) {
  TechniqueParams params;
  params.set("csm.terms", 3);
  int recipes = 0;
  for (const auto& row : technique_registry()) {
    if (!row.verify) continue;
    ++recipes;
    const auto technique = make_technique(row.name, params);
    EXPECT_EQ(Basis::parse(row.verify->lp_basis(params)).size(), technique->basis().size())
        << row.name;
    EXPECT_LT(row.verify->lo, row.verify->hi) << row.name;
    if (row.verify->judge == VerifyRecipe::Judge::StorageBox) {
      // Its moment bias, which verify allows above the box's bound; a row without one (vsm_16bit)
      // is allowed none.
      const bool biased = std::any_of(row.options.begin(), row.options.end(),
                                      [](const TechniqueOption* o) { return o->moment_bias; });
      EXPECT_EQ(row.verify->alpha != nullptr, biased) << row.name;
      EXPECT_NE(technique->storage().kind, StorageKind::Double) << row.name;
    }
  }
  EXPECT_EQ(recipes, 16);
}

// The default lists of `sweep` and `verify` and the sweep report's claims come from the rows:
// each reference is a technique of its family, places are unique, and the rows that solve the
// continuous Problem 1 on [0, 1] in closed form are sweep references beside their LP.
TEST(TechniqueRegistry, DefaultListsAndClaimsComeFromTheRows) {
  const TechniqueParams params;
  std::set<std::string> references;
  std::set<int> classic_places, verify_places;
  for (const SweepReference& r : sweep_references(TechniqueFamily::HardShadow)) {
    EXPECT_EQ(make_technique(r.name, params)->name(), r.name);
    references.insert(r.name);
    if (!r.expectation.empty()) {
      EXPECT_TRUE(classic_places.insert(r.place).second) << r.name;
    }
    if (!r.moments.empty()) {
      EXPECT_GT(r.seed_error, 0) << r.name;
    }
  }
  EXPECT_EQ(classic_places.size(), 6u);
  for (const SweepReference& r : sweep_references(TechniqueFamily::Transmittance))
    EXPECT_NE(find_technique(r.name, TechniqueFamily::Transmittance), nullptr) << r.name;
  for (const auto& row : technique_registry())
    if (row.verify_place > 0) {
      EXPECT_TRUE(row.verify.has_value()) << row.name;
      EXPECT_TRUE(verify_places.insert(row.verify_place).second) << row.name;
    }
  EXPECT_EQ(verify_default_list().front(), '[');
  std::vector<std::string> continuous;
  for (const TechniqueRow* row : family_rows(TechniqueFamily::HardShadow))
    if (const std::string lp = continuous_lp_of(*row); !lp.empty()) {
      continuous.push_back(row->name + " " + lp);
      EXPECT_TRUE(references.count(lp) && references.count(row->name)) << row->name;
    }
  EXPECT_EQ(continuous, (std::vector<std::string>{"hausdorff4 lp:power4", "tmsm lp:trig4"}));
}

TEST(TechniqueRegistry, OptionsAreDeclaredOnceAndReadIntoTheirFields) {
  std::set<std::string> keys;
  for (const auto& spec : technique_option_specs({TechniqueFamily::HardShadow}))
    EXPECT_TRUE(keys.insert(spec.name).second) << spec.name << " is declared twice";
  for (const TechniqueRow* row : family_rows(TechniqueFamily::HardShadow))
    for (const TechniqueOption* o : row->options)
      EXPECT_TRUE(keys.count(o->spec.name)) << row->name;
  Config config(technique_option_specs({TechniqueFamily::HardShadow}));
  config.set("esm.c=33");
  config.set("lvsm.layers=3");
  config.set("esm.zmax_offset=0.25");
  TechniqueParams params;
  read_technique_options(config, params);
  EXPECT_EQ(params.number("esm.c"), 33);
  EXPECT_EQ(params.integer("lvsm.layers"), 3);
  EXPECT_EQ(params.number("esm.zmax_offset"), 0.25);
  EXPECT_EQ(params.number("hamburger4.alpha"), 1e-10);  // the declared default
}

TEST(TechniqueRegistry, MomentBiasReplacesEveryAlphaAndIsChecked) {
  TechniqueParams params;
  set_moment_bias(params, 0.125);
  EXPECT_EQ(params.number("hamburger4.alpha"), 0.125);
  EXPECT_EQ(params.number("hamburger4_16bit.alpha"), 0.125);
  EXPECT_EQ(params.number("tmsm_float.alpha"), 0.125);
  EXPECT_EQ(params.number("esm.c"), TechniqueParams().number("esm.c"));  // not an alpha
  params.set("hamburger6.alpha", 1);
  EXPECT_THROW(make_technique("vsm", params), InputError);
  // Each alpha's record declares the range the check enforces, so that `options` and the user
  // guide print it.
  for (const TechniqueRow& row : technique_registry())
    for (const TechniqueOption* o : row.options)
      if (o->moment_bias) {
        EXPECT_EQ(o->spec.min, 0) << o->spec.name;
        EXPECT_EQ(o->spec.max, 1) << o->spec.name;
      }
}

// A 9x9 kernel of equal weights: every tap at `far` but the 2x2 block the custom PCF reads.
struct Kernel {
  std::vector<double> depths = std::vector<double>(81, 0.3),
                      weights = std::vector<double>(81, 1.0 / 81);
  double moment = 0;
  FragmentInput input(double zf, double c) {
    moment = 0;
    for (size_t t = 0; t < depths.size(); ++t) moment += weights[t] * std::exp(c * depths[t]);
    FragmentInput in;
    in.moments = {&moment, 1};
    in.zf = zf;
    in.kernel_depths = depths;
    in.kernel_weights = weights;
    return in;
  }
};

TEST(EsmFallback, WithoutADeeperTexelBothAreEsm) {
  TechniqueParams params;
  Kernel k;  // every tap at 0.3, in front of z_f = 0.5: ESM's assumption holds
  auto esm = make_technique("esm", params);
  for (const char* name : {"esm_zmax", "esm_threshold"}) {
    auto t = make_technique(name, params);
    EXPECT_EQ(t->shadow(k.input(0.5, params.number("esm.c"))),
              esm->shadow(k.input(0.5, params.number("esm.c"))))
        << name;
    EXPECT_EQ(t->fallbacks(), 0u) << name;
  }
}

TEST(EsmFallback, AFailingFragmentGetsTheTwoByTwoCustomPcf) {
  TechniqueParams params;
  const double c = params.number("esm.c"), zf = 0.5;
  Kernel k;
  // The 2x2 block at the centre (taps 40, 41, 49, 50): two occluders at 0.2, two surfaces at 0.9
  // behind the receiver; the rest of the kernel at 0.95, behind too, so both classifiers fail.
  std::fill(k.depths.begin(), k.depths.end(), 0.95);
  k.depths[40] = k.depths[50] = 0.2;
  k.depths[41] = k.depths[49] = 0.9;
  const double expected = 1 - 0.25 * (2 * std::exp(c * (0.2 - zf)) + 2 * 1.0);
  for (const char* name : {"esm_zmax", "esm_threshold"}) {
    auto t = make_technique(name, params);
    EXPECT_NEAR(t->shadow(k.input(zf, c)), expected, 1e-15) << name;
    EXPECT_EQ(t->fallbacks(), 1u) << name;
  }
  // Plain ESM clamps its Markov bound to 0 there: fully lit, the artefact the fall-back removes.
  EXPECT_EQ(make_technique("esm", params)->shadow(k.input(zf, c)), 0);
}

TEST(EsmFallback, ZmaxOffsetAndThresholdDecide) {
  TechniqueParams params;
  Kernel k;
  k.depths[0] = 0.505;  // one texel just behind z_f = 0.5, within the default offset 0.01
  auto zmax = make_technique("esm_zmax", params);
  zmax->shadow(k.input(0.5, params.number("esm.c")));
  EXPECT_EQ(zmax->fallbacks(), 0u);
  params.set("esm.zmax_offset", 0.001);
  zmax = make_technique("esm_zmax", params);
  zmax->shadow(k.input(0.5, params.number("esm.c")));
  EXPECT_EQ(zmax->fallbacks(), 1u);
  // Threshold: the filtered value (1/81) e^{80 * 0.005} + (80/81) e^{-16} is about 0.0184 < 1.01.
  auto threshold = make_technique("esm_threshold", params);
  threshold->shadow(k.input(0.5, params.number("esm.c")));
  EXPECT_EQ(threshold->fallbacks(), 0u);
}

}  // namespace
}  // namespace mb

namespace mb {
namespace {

// A row's catalog_basis is what a transparency sweep's report looks its basis up by among the
// candidates (docs/transparency.md §7): each name must be a catalog name exactly as candidates
// spell them, and the MBOIT rows that the catalog can express must have one.
TEST(TechniqueRegistry, CatalogBasesAreCatalogNames) {
  const std::vector<std::string>& catalog = catalog_names();
  int with_basis = 0;
  for (const TechniqueRow& row : technique_registry()) {
    if (row.catalog_basis.empty()) continue;
    ++with_basis;
    EXPECT_FALSE(row.catalog_basis_label.empty()) << row.name;
    for (const auto& f : row.catalog_basis)
      EXPECT_NE(std::find(catalog.begin(), catalog.end(), f), catalog.end())
          << row.name << ": " << f;
  }
  EXPECT_EQ(with_basis, 3);  // MBOIT power4, power6 and trig2
}

}  // namespace
}  // namespace mb

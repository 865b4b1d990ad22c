// The species section: each species' name, density and diameter or size law.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "scene/did_you_mean.hpp"
#include "scene/sections/sections.hpp"

namespace sphdem {

namespace {

// species.N.size_distribution: one of the laws of size_distribution.hpp. Only the keys
// of the chosen law are allowed. Nothing when the law or one of its values is bad.
std::optional<SizeDistribution> read_size_distribution(const YAML::Node& node,
                                                       const std::string& path,
                                                       SceneProblems& problems) {
  MapReader r(node, path, problems);
  SizeDistribution L;
  if (!r.has("law")) {
    r.fail(r.key("law"),
           fmt::format("is required: one of {}", fmt::join(choices_of(r.row("law")), ", ")));
    r.finish(false);  // which keys apply depends on the law
    return std::nullopt;
  }
  const std::optional<std::string> law_given = r.choice("law");
  if (!law_given) {
    r.finish(false);
    return std::nullopt;
  }
  const std::string& law = *law_given;
  auto bounds = [&] {
    L.min = r.required("min");
    L.max = r.required("max");
    if (r.clean() && L.max <= L.min)
      r.fail(r.key("max"), fmt::format("must be > min = {} (got {})", L.min, L.max));
  };
  if (law == "list") {
    L.law = SizeLaw::kList;
    const auto diameters = r.numbers("diameters");
    if (!r.has("fractions"))
      r.fail(r.key("fractions"), "is required: one fraction per diameter, summing to 1");
    else if (const auto fractions = r.numbers("fractions")) {
      L.fractions = *fractions;
      if (diameters && L.fractions.size() != diameters->size())
        r.fail(r.key("fractions"),
               fmt::format("must have one entry per diameter ({} diameters, {} fractions)",
                           diameters->size(), L.fractions.size()));
      check_sum_to_one(r, "fractions", L.fractions);
    }
    if (diameters) {
      L.diameters = *diameters;
      std::vector<double> sorted = L.diameters;
      std::sort(sorted.begin(), sorted.end());
      for (std::size_t i = 1; i < sorted.size(); ++i)
        if (sorted[i] == sorted[i - 1]) {
          r.fail(r.key("diameters"),
                 fmt::format("each diameter may appear once ({} is given twice)", sorted[i]));
          break;
        }
      L.min = sorted.front();
      L.max = sorted.back();
    }
    if (!r.has("basis"))
      r.fail(r.key("basis"), "is required: number or volume (what the fractions count)");
    else
      L.by_volume = r.choice("basis") == std::optional<std::string>("volume");
  } else if (law == "uniform") {
    L.law = SizeLaw::kUniform;
    bounds();
  } else {
    const bool normal = law == "normal";
    L.law = normal ? SizeLaw::kNormal : SizeLaw::kLognormal;
    if (normal) {
      L.mean = r.required("mean");
      L.std = r.required("std");
    } else {
      L.median = r.required("median");
      L.sigma_ln = r.required("sigma_ln");
    }
    bounds();
    const double kept = r.clean() ? truncation_mass(L) : 1.0;
    if (!(kept >= 1e-3))
      r.fail(
          r.key("min"),
          fmt::format("the truncation [min, max] = [{}, {}] keeps only {:.3g} % of the {} law; "
                      "it must keep at least 0.1 % (check {}, min and max)",
                      L.min, L.max, 100.0 * kept, law, normal ? "mean, std" : "median, sigma_ln"));
  }
  const bool ok = r.clean();
  r.finish();
  return ok ? std::optional<SizeDistribution>(L) : std::nullopt;
}

void write_size_distribution(YAML::Emitter& e, const SizeDistribution& L) {
  e << YAML::Key << "size_distribution" << YAML::Value << YAML::BeginMap << YAML::Key << "law"
    << YAML::Value << size_law_name(L.law);
  switch (L.law) {
    case SizeLaw::kList:
      e << YAML::Key << "diameters" << YAML::Value << YAML::Flow << L.diameters << YAML::Key
        << "fractions" << YAML::Value << YAML::Flow << L.fractions << YAML::Key << "basis"
        << YAML::Value << (L.by_volume ? "volume" : "number");
      break;
    case SizeLaw::kNormal:
      e << YAML::Key << "mean" << YAML::Value << L.mean << YAML::Key << "std" << YAML::Value
        << L.std;
      break;
    case SizeLaw::kLognormal:
      e << YAML::Key << "median" << YAML::Value << L.median << YAML::Key << "sigma_ln"
        << YAML::Value << L.sigma_ln;
      break;
    default:
      break;
  }
  if (L.law != SizeLaw::kList)
    e << YAML::Key << "min" << YAML::Value << L.min << YAML::Key << "max" << YAML::Value << L.max;
  e << YAML::EndMap;
}

}  // namespace

// Species with a problem are kept (so that groups naming them find them) but marked in
// cx.species_ok: the checks that need their sizes are skipped.
void read_species(MapReader& top, Scene& sc, ReadContext& cx) {
  const YAML::Node list = top.child("species");
  if (list && !list.IsSequence())
    top.fail("species", "must be a list of {name, diameter, density}");
  for (std::size_t s = 0; list && list.IsSequence() && s < list.size(); ++s) {
    MapReader r(list[s], fmt::format("species.{}", s), cx.problems);
    SpeciesSpec sp;
    sp.name = r.text("name");
    if (sp.name.empty() || sp.name.find_first_of(":, ") != std::string::npos)
      r.fail(r.key("name"), "must be a non-empty name without ':', ',' or spaces");
    else if (sc.species_index(sp.name) >= 0)
      r.fail(r.key("name"), "duplicate species name '" + sp.name + "'");
    const bool one_size = r.has("diameter"), law = r.has("size_distribution");
    if (one_size && law) {
      r.fail(r.key("size_distribution"),
             "give either 'diameter' (one size) or 'size_distribution', not both");
    } else if (law) {
      const auto size = read_size_distribution(r.child("size_distribution"),
                                               r.key("size_distribution"), cx.problems);
      if (size) {
        sp.size = *size;
        sp.diameter = sauter_mean(sp.size);
      }
    } else if (!one_size) {
      r.fail(r.key("diameter"), "is required: a number in (0, inf], or give 'size_distribution'");
    } else {
      sp.diameter = r.required("diameter");
      sp.size.min = sp.size.max = sp.diameter;
    }
    sp.density = r.required("density");
    cx.species_ok.push_back(r.clean());
    r.finish();
    sc.species.push_back(sp);
  }
}

void write_species(YAML::Emitter& e, const Scene& sc) {
  e << YAML::Key << "species" << YAML::Value << YAML::BeginSeq;
  for (const auto& s : sc.species) {
    e << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << s.name;
    if (s.monodisperse())
      e << YAML::Key << "diameter" << YAML::Value << s.diameter;
    else
      write_size_distribution(e, s.size);
    e << YAML::Key << "density" << YAML::Value << s.density << YAML::EndMap;
  }
  e << YAML::EndSeq;
}

bool known_species(MapReader& r, const Scene& sc, const std::string& key, const std::string& name) {
  if (sc.species_index(name) >= 0) return true;
  std::vector<std::string> names;
  for (const auto& s : sc.species) names.push_back(s.name);
  r.fail(key, fmt::format("'{}' is not a species listed under 'species'{}", name,
                          did_you_mean(name, names)));
  return false;
}

void check_sum_to_one(MapReader& r, const std::string& k, const std::vector<double>& f) {
  double sum = 0.0;
  for (double x : f) sum += x;
  if (std::abs(sum - 1.0) > 1e-6) r.fail(r.key(k), fmt::format("must sum to 1 (got {})", sum));
}

}  // namespace sphdem

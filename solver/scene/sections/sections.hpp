#pragma once
// The sections of a scene file, each read and written by a pair of functions that stand
// side by side in the section's file: read_X takes the section's keys through the scene
// key table (scene/scene_keys.hpp) into the Scene, write_X emits them as case.yaml holds
// them (every key, resolved). scene_loader.cpp calls the readers in the file's order,
// then resolves the automatic values; scene_to_yaml calls the writers in the same order.
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "scene/fidelity.hpp"
#include "scene/map_reader.hpp"
#include "scene/scene.hpp"
#include "scene/scene_problems.hpp"

namespace sphdem {

// What the reading of one section hands on to the sections after it and to the
// resolution of the automatic values.
struct ReadContext {
  SceneProblems& problems;
  const FidelityPreset* preset = nullptr;  // the scene's fidelity: its values are defaults
  bool box_ok = true;                      // domain.size read without a problem
  std::vector<bool> species_ok = {};       // per species: read without a problem
  bool resolution_given = false;           // fluid.resolution in the file (not a preset's)
  bool stiffness_auto = true;              // contact.stiffness: auto
  bool kernel_auto = true;                 // coupling.sphere_kernel_scale: auto
  bool density_alarm_auto = true;          // watchdog.density_error: auto
  bool drag_kernel_given = false;          // coupling.drag_kernel_scale in the file
};

// name, description, fidelity, domain, gravity
void read_top(MapReader& top, Scene& sc, ReadContext& cx);
void write_top(YAML::Emitter& e, const Scene& sc);
void read_fluid(MapReader& top, Scene& sc, ReadContext& cx);
void write_fluid(YAML::Emitter& e, const Scene& sc);
// species, with their size laws
void read_species(MapReader& top, Scene& sc, ReadContext& cx);
void write_species(YAML::Emitter& e, const Scene& sc);
void read_particles(MapReader& top, Scene& sc, ReadContext& cx);
void write_particles(YAML::Emitter& e, const Scene& sc);
// contact, with its tangential and rolling parts
void read_contact(MapReader& top, Scene& sc, ReadContext& cx);
void write_contact(YAML::Emitter& e, const Scene& sc);
// drag and coupling
void read_coupling(MapReader& top, Scene& sc, ReadContext& cx);
void write_coupling(YAML::Emitter& e, const Scene& sc);
// the imposed flow of a column periodic in z
void read_flow(MapReader& top, Scene& sc, ReadContext& cx);
void write_flow(YAML::Emitter& e, const Scene& sc);
// time, startup, output, checkpoint, watchdog
void read_run_control(MapReader& top, Scene& sc, ReadContext& cx);
void write_run_control(YAML::Emitter& e, const Scene& sc);
void read_insitu(MapReader& top, Scene& sc, ReadContext& cx);
void write_insitu(YAML::Emitter& e, const Scene& sc);

// Helpers the sections share.
void emit_vec3(YAML::Emitter& e, const std::array<double, 3>& v);
// A species name a group or key refers to: one listed under 'species' (a misspelling
// gets a did-you-mean). False when it is not.
bool known_species(MapReader& r, const Scene& sc, const std::string& key, const std::string& name);
// Fractions that must sum to 1 (number fractions of a mixture, list-law fractions).
void check_sum_to_one(MapReader& r, const std::string& k, const std::vector<double>& f);

}  // namespace sphdem

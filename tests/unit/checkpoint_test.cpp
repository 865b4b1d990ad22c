// Checkpoints: the file (every entry type back bit for bit; a damaged or cut file
// refused), the field registry (every member listed, halo tags true), and a run
// continued from a checkpoint repeating the uninterrupted run bit for bit, on one thread
// and on two, for the couplings, the double smoothing, friction with rolling (contact
// history) and rigid blocks.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "domain/state_snapshot.hpp"
#include "io/checkpoint_file.hpp"
#include "propagator/simulation.hpp"
#include "scene/scene.hpp"

using namespace sphdem;
namespace fs = std::filesystem;

namespace {

std::string temp_path(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "sphdem_checkpoint_test";
  fs::create_directories(dir);
  return (dir / name).string();
}

void write_sample(const std::string& path) {
  CheckpointWriter w(path);
  w.array("fluid/x", std::vector<double>{1.0, -2.5, 1e-300, std::nan("")});
  w.array("fluid/id", std::vector<std::int64_t>{-1, 0, 1LL << 62});
  w.array("spheres/group", std::vector<std::int32_t>{-1, 7});
  w.array("spheres/species", std::vector<std::uint16_t>{0, 65535});
  w.array("fluid/kind", std::vector<std::uint8_t>{0, 1, 1});
  w.array("empty", std::vector<double>{});
  w.scalar("run/time", 0.125);
  w.scalar<std::int64_t>("run/step", 42);
  w.text("scene/yaml", "name: test\nfluid: {density: 1000}\n");
  w.finish();
}

// Offset of a byte sequence in a file (the data of a dataset, to damage it).
std::size_t find_bytes(const std::string& path, const void* data, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = all.find(std::string(static_cast<const char*>(data), n));
  return at;
}

TEST(CheckpointFile, EveryEntryTypeComesBackBitForBit) {
  const std::string path = temp_path("sample.h5");
  write_sample(path);
  const CheckpointReader r(path);
  const auto x = r.array<double>("fluid/x");
  ASSERT_EQ(x.size(), 4u);
  const double want[4] = {1.0, -2.5, 1e-300, std::nan("")};
  EXPECT_EQ(std::memcmp(x.data(), want, sizeof want), 0);
  EXPECT_EQ(r.array<std::int64_t>("fluid/id"), (std::vector<std::int64_t>{-1, 0, 1LL << 62}));
  EXPECT_EQ(r.array<std::int32_t>("spheres/group"), (std::vector<std::int32_t>{-1, 7}));
  EXPECT_EQ(r.array<std::uint16_t>("spheres/species"), (std::vector<std::uint16_t>{0, 65535}));
  EXPECT_EQ(r.array<std::uint8_t>("fluid/kind"), (std::vector<std::uint8_t>{0, 1, 1}));
  EXPECT_TRUE(r.array<double>("empty").empty());
  EXPECT_EQ(r.scalar<double>("run/time"), 0.125);
  EXPECT_EQ(r.scalar<std::int64_t>("run/step"), 42);
  EXPECT_EQ(r.text("scene/yaml"), "name: test\nfluid: {density: 1000}\n");
  EXPECT_EQ(r.names("fluid/"), (std::vector<std::string>{"id", "kind", "x"}));
  EXPECT_THROW(r.array<double>("fluid/id"), CheckpointError);  // another type
  EXPECT_THROW(r.scalar<double>("run/nothing"), CheckpointError);
}

TEST(CheckpointFile, OneFlippedBitIsRefused) {
  const std::string path = temp_path("flipped.h5");
  write_sample(path);
  const double marker[2] = {1.0, -2.5};  // the first two values of fluid/x
  const std::size_t at = find_bytes(path, marker, sizeof marker);
  ASSERT_NE(at, std::string::npos);
  {
    std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
    f.seekg(static_cast<std::streamoff>(at + 3));
    char c = 0;
    f.read(&c, 1);
    c ^= 0x10;
    f.seekp(static_cast<std::streamoff>(at + 3));
    f.write(&c, 1);
  }
  try {
    CheckpointReader r(path);
    FAIL() << "a damaged file was read";
  } catch (const CheckpointError& e) {
    EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(CheckpointFile, AFileCutShortOrUnfinishedIsRefused) {
  const std::string path = temp_path("cut.h5");
  write_sample(path);
  const auto size = fs::file_size(path);
  for (const double keep : {0.0, 0.3, 0.9}) {
    const std::string cut = temp_path("cut_part.h5");
    fs::copy_file(path, cut, fs::copy_options::overwrite_existing);
    fs::resize_file(cut, static_cast<std::uintmax_t>(keep * static_cast<double>(size)));
    EXPECT_THROW(CheckpointReader r(cut), CheckpointError) << "kept " << keep;
  }
  const std::string unfinished = temp_path("unfinished.h5");
  {
    CheckpointWriter w(unfinished);
    w.scalar("run/time", 1.0);
  }  // no finish(): no checksum
  EXPECT_THROW(CheckpointReader r(unfinished), CheckpointError);
}

TEST(CheckpointFile, AnUnwritableFileIsAClearError) {
  try {
    CheckpointWriter w("/nonexistent-dir/x.h5");
    FAIL();
  } catch (const CheckpointError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.h5"), std::string::npos);
  }
}

// ---------------------------------------------------------------- field registry

template <class P>
void expect_every_member_listed() {
  P p;
  std::set<const void*> seen;
  int n = 0, state = 0;
  p.for_each_field([&](const FieldInfo& f, auto& v) {
    seen.insert(&v);
    ++n;
    state += f.state();
    EXPECT_TRUE(!f.constant() || f.state()) << f.name;
  });
  EXPECT_EQ(n, P::kFieldCount);
  EXPECT_EQ(static_cast<int>(seen.size()), P::kFieldCount);  // each member once
  const P& c = p;
  int nc = 0;
  c.for_each_field([&](const FieldInfo&, const auto&) { ++nc; });  // the const overload
  EXPECT_EQ(nc, n);
  EXPECT_GT(state, 0);
}

TEST(FieldRegistry, EveryMemberIsListedOnce) {
  expect_every_member_listed<FluidParticles>();
  expect_every_member_listed<DemParticles>();
}

// A snapshot keeps exactly the fields the registry tags state and not constant: restored
// for some particles, those get their values back and the rest keep theirs; the constant
// and scratch fields are never touched.
template <class P>
void expect_snapshot_by_tags() {
  P p;
  const std::size_t n = 5;
  p.resize(n);
  p.n_owned = n;
  // a value of the field's own type, distinct per field, particle and fill (small types too)
  const auto value = [](const auto& v, int offset, int f, std::size_t i) {
    return static_cast<std::decay_t<decltype(v[0])>>(offset + 7 * f + static_cast<int>(i));
  };
  const auto fill = [&](int offset) {
    int f = 0;
    p.for_each_field([&](const FieldInfo&, auto& v) {
      for (std::size_t i = 0; i < n; ++i) v[i] = value(v, offset, f, i);
      ++f;
    });
  };
  const auto expect = [&](bool some) {  // some: only particles 1 and 3 restored
    int f = 0;
    p.for_each_field([&](const FieldInfo& field, const auto& v) {
      const bool kept = field.state() && !field.constant();
      for (std::size_t i = 0; i < n; ++i) {
        const bool back = kept && (!some || i == 1 || i == 3);
        EXPECT_EQ(v[i], value(v, back ? 0 : 100, f, i)) << field.name << " particle " << i;
      }
      ++f;
    });
  };
  fill(0);
  StateSnapshot snap;
  snap.save(p, n);
  fill(100);
  snap.restore(p, {1, 3});
  expect(true);
  snap.restore(p);
  expect(false);
  int changing = 0;
  p.for_each_field(
      [&](const FieldInfo& f, const auto&) { changing += f.state() && !f.constant(); });
  EXPECT_GT(changing, 0);
}

TEST(FieldRegistry, SnapshotKeepsTheChangingStateFields) {
  expect_snapshot_by_tags<DemParticles>();
  expect_snapshot_by_tags<FluidParticles>();
}

// After the fluid side is evaluated, every halo-tagged field's halo copies equal their
// owned sources (positions: an image, shifted by whole box lengths).
template <class P>
void expect_halo_copies_equal_sources(const P& p, const std::vector<std::uint32_t>& source,
                                      const Box& box, const char* what) {
  ASSERT_EQ(p.size(), p.n_owned + source.size()) << what;
  ASSERT_GT(source.size(), 0u) << what;
  p.for_each_field([&](const FieldInfo& f, const auto& v) {
    if (!f.halo()) return;
    ASSERT_EQ(v.size(), p.size()) << what << " " << f.name;
    const int axis = f.name[0] - 'x';  // for the positions
    std::size_t bad = 0;
    for (std::size_t g = 0; g < source.size(); ++g) {
      const double ghost = static_cast<double>(v[p.n_owned + g]);
      const double owned = static_cast<double>(v[source[g]]);
      if (f.flags & kPosition) {  // the same point or an image a box length away
        const double shift = std::abs(ghost - owned), L = box.length(axis);
        bad += shift > 1e-15 && std::abs(shift - L) > 1e-12 * L;
      } else {
        bad += !(ghost == owned);
      }
    }
    EXPECT_EQ(bad, 0u) << what << " field " << f.name;
  });
}

// ---------------------------------------------------------------- bit-exact restart

// Small scenes with every carried part: the default coupling (variational, split,
// delta-SPH) in a suspension; friction and rolling (contact history, spin) in a bed; the
// double smoothing with the interpolated coupling and a rigid bidisperse block.
const char* const kSuspension = R"(
name: suspension
domain: {size: [0.0016, 0.0016, 0.0016]}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: random, species: glass, min: [0, 0, 0], max: [0.0016, 0.0016, 0.001], voidage: 0.8, seed: 3}
startup: {relax_steps: 3}
)";
const char* const kFrictionBed = R"(
name: friction_bed
domain: {size: [0.0016, 0.0016, 0.0012]}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: lattice, species: glass, min: [0, 0, 0], max: [0.0016, 0.0016, 0.0003001], voidage: 0.4765,
     velocity: [0.005, 0.002, 0]}
contact:
  stiffness: 100
  restitution: 0.5
  tangential: {model: linear_history, friction: 0.5, restitution: 0.5}
  rolling: {model: epsd, friction: 0.1}
startup: {relax_steps: 2}
)";
const char* const kDoubleSmoothingBlock = R"(
name: block
domain: {size: [0.0016, 0.0016, 0.0016]}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4}
species: [{name: coarse, diameter: 1.5e-4, density: 2500}, {name: fine, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: lattice, species: [coarse, fine], fractions: [0.5, 0.5], seed: 1, voidage: 0.9,
     min: [0, 0, 0.0006], max: [0.0016, 0.0016, 0.0012], rigid: true}
contact: {model: linear_spring_dashpot, stiffness: 10, damping: 0}
drag: {law: beetstra}
coupling: {voidage_smoothing: double}
startup: {relax_steps: 3}
)";
// A bed on the distributor of a column periodic in z with a U ramp (issue 37): the mean
// pressure gradient G, which the controller carries from step to step, is in the checkpoint.
const char* const kPeriodicBed = R"(
name: periodic_bed
domain: {size: [0.0016, 0.0016, 0.0032], periodic_z: true}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: random, species: glass, voidage: 0.75, min: [0, 0, 0], max: [0.0016, 0.0016, 0.0016], seed: 3}
contact: {tangential: {model: linear_history, friction: 0.3}}
flow: {times: [0, 0.004], superficial_velocity: [0, 0.004], distributor: true, top_plane: 0.003}
startup: {relax_steps: 2}
)";

struct Threads {
  int saved = omp_get_max_threads();
  explicit Threads(int n) { omp_set_num_threads(n); }
  ~Threads() { omp_set_num_threads(saved); }
};

// Every field of the owned particles, byte for byte.
template <class P>
void expect_same_bits(const P& a, const P& b, const char* what) {
  ASSERT_EQ(a.n_owned, b.n_owned) << what;
  a.for_each_field([&](const FieldInfo& f, const auto& va) {
    b.for_each_field([&](const FieldInfo& g, const auto& vb) {
      if constexpr (std::is_same_v<decltype(va), decltype(vb)>) {
        if (std::strcmp(f.name, g.name) != 0) return;
        const std::size_t n = a.n_owned;
        ASSERT_GE(va.size(), n);
        ASSERT_GE(vb.size(), n);
        EXPECT_EQ(std::memcmp(va.data(), vb.data(), n * sizeof(va[0])), 0)
            << what << " field " << f.name << " differs";
      }
    });
  });
}

// Runs `before` steps (then on to the next checkpointable step), writes a checkpoint,
// runs `after` more; then a second Simulation from the file runs the same `after`
// steps. Everything must agree bit for bit.
void expect_exact_restart(const char* yaml, int threads, int before, int after) {
  const Threads team(threads);
  const Scene scene = load_scene_text(yaml, "restart_test");
  Simulation a(scene);
  a.set_sort_interval(7);  // several re-sorts within the test's steps
  a.relax();
  for (int k = 0; k < before || !a.rebuilds_all_next_step(); ++k) a.step();
  const std::string path = temp_path(scene.name + "_" + std::to_string(threads) + ".h5");
  {
    CheckpointWriter w(path);
    a.write_state(w);
    w.text("scene/yaml", scene_to_yaml(scene));
    w.finish();
  }
  const long at = a.step_count();
  for (int k = 0; k < after; ++k) a.step();

  const CheckpointReader r(path);
  const Scene again = load_scene_text(r.text("scene/yaml"), path);
  Simulation b(again, r);
  EXPECT_EQ(b.step_count(), at);
  for (int k = 0; k < after; ++k) b.step();
  EXPECT_EQ(a.step_count(), b.step_count());
  EXPECT_EQ(a.time(), b.time()) << a.time() - b.time();
  EXPECT_EQ(a.dt_sph(), b.dt_sph());
  expect_same_bits(a.fluid(), b.fluid(), "fluid");
  expect_same_bits(a.spheres(), b.spheres(), "spheres");
  const auto ra = a.contact_records(), rb = b.contact_records();
  ASSERT_EQ(ra.size(), rb.size());
  for (std::size_t k = 0; k < ra.size(); ++k) {
    EXPECT_EQ(ra[k].id, rb[k].id);
    EXPECT_EQ(ra[k].partner, rb[k].partner);
    EXPECT_EQ(std::memcmp(&ra[k].state, &rb[k].state, sizeof(ContactState)), 0);
  }
  // the continuation really moved the particles (the comparison is not of a frozen state)
  EXPECT_GT(a.time(), 0.0);
}

TEST(Restart, SuspensionOneThread) {
  expect_exact_restart(kSuspension, 1, 10, 23);
}
TEST(Restart, SuspensionTwoThreads) {
  expect_exact_restart(kSuspension, 2, 10, 23);
}
TEST(Restart, FrictionAndRollingOneThread) {
  expect_exact_restart(kFrictionBed, 1, 10, 23);
}
TEST(Restart, FrictionAndRollingTwoThreads) {
  expect_exact_restart(kFrictionBed, 2, 10, 23);
}
TEST(Restart, DoubleSmoothingRigidBlockOneThread) {
  expect_exact_restart(kDoubleSmoothingBlock, 1, 10, 23);
}
TEST(Restart, DoubleSmoothingRigidBlockTwoThreads) {
  expect_exact_restart(kDoubleSmoothingBlock, 2, 10, 23);
}
TEST(Restart, PeriodicBedWithAFlowTwoThreads) {
  expect_exact_restart(kPeriodicBed, 2, 10, 23);
}

TEST(FieldRegistry, HaloTagsHoldAfterAnEvaluation) {
  for (const char* yaml : {kSuspension, kFrictionBed, kDoubleSmoothingBlock}) {
    const Scene scene = load_scene_text(yaml, "halo_test");
    Simulation sim(scene);
    sim.relax();
    for (int k = 0; k < 5; ++k) sim.step();
    sim.refresh();  // every list anew, every field evaluated and its halo filled
    const Box& box = sim.params().box;
    expect_halo_copies_equal_sources(sim.fluid(), sim.fluid_halo().periodic().source(), box,
                                     scene.name.c_str());
    expect_halo_copies_equal_sources(sim.spheres(), sim.dem().halo().periodic().source(), box,
                                     scene.name.c_str());
  }
}

}  // namespace

#pragma once
// The instruction set the SPH pair passes run with: the x86-64 baseline on every CPU,
// AVX2 with fused multiply-add (x86-64-v3: the scalar row loops, compiled for it) where the
// CPU has that, or AVX-512 (x86-64-v4: gathers, eight lanes, fused multiply-add). One
// binary; the CPU is asked once. They give the same sums to round-off (unit tests compare
// them), not the same bits. Passes without an AVX2 form run the baseline under kAvx2.
namespace sphdem {

enum class PairIsa { kBaseline, kAvx2, kAvx512 };

// A row's cost beside its entries' (one each) when the pair passes split rows between
// threads (domain/row_partition.hpp).
inline constexpr double kPairRowCost = 4.0;

PairIsa best_pair_isa();

}  // namespace sphdem

// Marks a function compiled for x86-64-v4 (empty where that does not exist), with the
// functions it calls inlined into it (flatten: the row loops are written once, for both
// instruction sets; a build with -march=native, whose callees cannot be inlined into a
// narrower target, still compiles).
#if defined(__x86_64__) && defined(__GNUC__)
#define SPHDEM_TARGET_AVX512 [[gnu::target("arch=x86-64-v4"), gnu::flatten]]
#define SPHDEM_TARGET_AVX2 [[gnu::target("arch=x86-64-v3"), gnu::flatten]]
#else
#define SPHDEM_TARGET_AVX512
#define SPHDEM_TARGET_AVX2
#endif

#pragma once
// COMMINUTE_VECTOR_CLONES before a function with a vectorised loop: AVX-512 and AVX2 versions of it
// beside the baseline one, chosen once by the processor at load time (GCC function
// multiversioning). The same operations in each, so the same results bit for bit, provided the
// room is compiled without contraction into fused multiply-adds (-ffp-contract=off, which the
// AVX2 and AVX-512 versions could otherwise form; src/comminute/CMakeLists.txt). Only where the
// build defines COMMINUTE_AVX2_CLONES (Release: the sanitizers' run-time libraries start after
// the choice is made). Not for virtual functions (GCC cannot multiversion them): a virtual one
// calls a cloned one.
#if defined(COMMINUTE_AVX2_CLONES)
#define COMMINUTE_VECTOR_CLONES [[gnu::target_clones("avx512f", "avx2", "default")]]
#else
#define COMMINUTE_VECTOR_CLONES
#endif

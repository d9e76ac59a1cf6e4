#pragma once
// A counting replacement of the global operator new for the zero-allocation tests (real-time discipline,
// DEVELOPERS.md): a test binary that links the `tomc_counting_allocator` object library counts every
// operator new of the process; the test reads allocation_count() before and after the cyclic code. Each such
// test is its own binary, so that the count sees only that test.
#include <cstdint>

namespace tomc::testing {

std::uint64_t allocation_count() noexcept;

}  // namespace tomc::testing

// The counting operator new is linked in and counts (otherwise every zero-allocation test would pass
// vacuously): one allocation of each form is one count.
#include <gtest/gtest.h>

#include <memory>
#include <new>
#include <vector>

#include "counting_allocator.hpp"

// tomc's own: the counter behind ARCHITECTURE-GUIDE §7's "no allocation in the cyclic path" must see every
// operator new.
TEST(CountingAllocator, CountsEveryOperatorNew) {
  const auto before = tomc::testing::allocation_count();
  auto single = std::make_unique<int>(7);
  auto array = std::make_unique<int[]>(3);
  int* nothrow = new (std::nothrow) int(1);
  delete nothrow;
  EXPECT_EQ(tomc::testing::allocation_count() - before, 3u);
  std::vector<double> v(100);
  EXPECT_EQ(tomc::testing::allocation_count() - before, 4u);
  EXPECT_EQ(*single + array[0] + static_cast<int>(v[0]), 7);
}

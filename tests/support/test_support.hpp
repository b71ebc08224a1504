// Shared helpers for the GoogleTest suites: those of test_files.hpp (temporary folders, fixture
// paths, files, commands, contains) and the skip used when ../shared/data is absent.
#pragma once

#include <gtest/gtest.h>

#include "tests/support/test_files.hpp"

// Declares `dataDir` (a std::filesystem::path to ../shared/data) or skips the test with a message.
#define CLM3D_REQUIRE_SHARED_DATA(dataDir)                                        \
  const auto dataDir##_optional = ::clm3d::sharedDataDir();                       \
  if (!dataDir##_optional) {                                                      \
    GTEST_SKIP() << "../shared/data not found (set CLM3D_DATA to run this test)"; \
  }                                                                               \
  const std::filesystem::path dataDir = *dataDir##_optional

#include "core/common/data_paths.hpp"

// SPDX-License-Identifier: MIT
#pragma once
// The libFuzzer entry point every target in tests/fuzz defines. Built with clang and
// -fsanitize=fuzzer it is driven by libFuzzer; in the normal build replay_main.cpp calls it on
// every file of the seed corpus and of the crashes found, as a regression test.

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

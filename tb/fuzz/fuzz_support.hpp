// What the fuzz targets share: a scratch file per process for the loaders
// that read by path, and seed writing (CUBE4_FUZZ_SEEDS=DIR: write the seed
// corpus there and exit, run by run_fuzzer.cmake before fuzzing).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cube4::fuzz {

using Bytes = std::vector<unsigned char>;

// Rewrites this process's scratch file (name ending in `suffix`) with the input.
const std::string& scratch_file(const std::string& suffix, const uint8_t* data, size_t size);

// Each target defines it: writes its seed corpus into dir. With
// CUBE4_FUZZ_SEEDS=DIR set, the fuzzer (LLVMFuzzerInitialize, in
// fuzz_support.cpp) calls it and exits.
void write_seeds(const std::string& dir);
void write_seed(const std::string& dir, const std::string& name, const Bytes& b);
Bytes gzip(const Bytes& in);


}  // namespace cube4::fuzz

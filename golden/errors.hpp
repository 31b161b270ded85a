// Bad input (a file, a scene key, a value) is an InputError: the CLI exits 2.
// Everything else that goes wrong is internal: exit 1.
#pragma once
#include <stdexcept>
#include <string>

namespace cube4::golden {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace cube4::golden

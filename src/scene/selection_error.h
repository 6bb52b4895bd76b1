// The caller asked for something the file does not have (a scene index, a
// camera node): the file is fine, the request is wrong. A command line turns
// it into a usage error of the flag that made the request.
#pragma once

#include <string>

#include "core/error.h"

namespace lensrt {

class SelectionError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace lensrt

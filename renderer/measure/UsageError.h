// Bad input to a measurement (an unknown technique, key or value, a camera the scene lacks):
// the message names the option or file and the problem. shadowlab-cli prints it on one line
// and exits with 2; the GUI shows it in the panel that asked.
#pragma once

#include <stdexcept>

namespace sl::measure {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace sl::measure

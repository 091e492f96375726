#pragma once
// The programs and files the tests start or read, from the compile definitions of gdnav_test_support.
#include <string>

namespace gdnav::testing {

// The gdnav executable of this build.
inline const std::string kExe = GDNAV_GDNAV_EXE;

}  // namespace gdnav::testing

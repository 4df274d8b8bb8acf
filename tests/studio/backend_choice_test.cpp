// Tests for app/common/backend_choice.cpp: a backend is chosen by name, and a name that is not one
// is refused instead of falling back to some backend (the studio's script and panel use it).
#include "backend_choice.h"

#include "core/input_error.h"

#include <gtest/gtest.h>

namespace paver::app {
namespace {

TEST(BackendChoice, UnknownNamesAreRefused) {
  for (const char* name : {"gpu", "Vulkan", "", "cpu "}) {
    try {
      choose_backend(name, "", 1);
      ADD_FAILURE() << "accepted backend '" << name << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("use cpu, vulkan or auto"), std::string::npos) << e.what();
    }
  }
}

TEST(BackendChoice, CpuIsTheReference) {
  const BackendChoice cpu = choose_backend("cpu", "", 1);
  EXPECT_EQ(cpu.name, "cpu");
  EXPECT_TRUE(cpu.device.empty());
  EXPECT_TRUE(bool(cpu.factory));
}

}  // namespace
}  // namespace paver::app

// The main of the tests that draw with OpenGL ES. A test fails when it set a uniform that no
// source of its program declares (gpu/program.hpp), which the GL itself skips silently, or
// when it ends with the GL away from rest (gpu/pipeline.hpp): a pass, or the test itself, left
// its state behind. Such a test is reported after its own result (a uniform set outside any
// test, by the next test to end), and the run's status is a failure.

#include <cstdio>
#include <string>
#include <vector>

#include <EGL/egl.h>
#include <gtest/gtest.h>

#include "gpu/pipeline.hpp"
#include "gpu/program.hpp"

namespace {

class PassChecks : public ::testing::EmptyTestEventListener {
  public:
    void OnTestEnd(const ::testing::TestInfo& test) override {
        std::vector<std::string> wrong = gem::gpu::take_unknown_uniforms();
        // Where the test made a context: the tests share one (gpu_test_support.hpp).
        if (eglGetCurrentContext() != EGL_NO_CONTEXT) {
            const std::string left = gem::gpu::state_left_behind();
            if (!left.empty()) wrong.push_back("the GL is left away from rest: " + left);
        }
        for (const std::string& w : wrong) {
            std::printf("[  FAILED  ] %s.%s: %s\n", test.test_suite_name(), test.name(), w.c_str());
            failed = true;
        }
    }
    bool failed = false;
};

}  // namespace

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    auto* checks = new PassChecks;  // the listeners list owns it
    ::testing::UnitTest::GetInstance()->listeners().Append(checks);
    const int status = RUN_ALL_TESTS();
    return status != 0 || checks->failed ? 1 : 0;
}

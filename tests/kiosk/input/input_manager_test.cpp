// InputManager's discovery and hotplug plumbing on a temporary directory (no /dev/input here):
// files that are not evdev devices, nodes whose permissions come late, a missing directory.
// Log lines are read back from stderr, where the kiosk logs.

#include "input/input_manager.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace gem::kiosk {
namespace {

// Sends stderr to a file while alive; lines() reads what was written since the last call.
class StderrCapture {
  public:
    StderrCapture() {
        std::fflush(stderr);
        file_ = std::tmpfile();
        saved_ = ::dup(STDERR_FILENO);
        ::dup2(::fileno(file_), STDERR_FILENO);
    }
    ~StderrCapture() {
        ::dup2(saved_, STDERR_FILENO);
        ::close(saved_);
        std::fclose(file_);
    }
    std::vector<std::string> lines() {
        std::vector<std::string> result;
        const off_t end = ::lseek(::fileno(file_), 0, SEEK_END);
        std::string text(static_cast<std::size_t>(end - read_), '\0');
        if (!text.empty()) {
            [[maybe_unused]] const ssize_t got =
                ::pread(::fileno(file_), text.data(), text.size(), read_);
        }
        read_ = end;
        std::istringstream stream(text);
        for (std::string line; std::getline(stream, line);) result.push_back(line);
        return result;
    }

  private:
    std::FILE* file_ = nullptr;
    int saved_ = -1;
    off_t read_ = 0;
};

class InputManagerTest : public ::testing::Test {
  protected:
    void SetUp() override {
        char pattern[] = "/tmp/gem-input-test-XXXXXX";
        ASSERT_NE(::mkdtemp(pattern), nullptr);
        dir_ = pattern;
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::string path(const std::string& name) const { return dir_ + "/" + name; }
    void create(const std::string& name) { std::ofstream(path(name)) << "not a device\n"; }

    InputOptions options() const {
        InputOptions o;
        o.device_dir = dir_;
        return o;
    }

    std::string dir_;
};

bool mentions(const std::string& line, const std::string& what) {
    return line.find(what) != std::string::npos;
}

TEST_F(InputManagerTest, NonEvdevFileAppearingAndVanishing) {
    StderrCapture capture;
    int opened = 0;
    int closed = 0;
    InputManager manager(
        options(),
        [&](const std::string& p) {
            ++opened;
            return open_device_node(p);
        },
        [&](int fd) {
            ++closed;
            close_device_node(fd);
        });
    ASSERT_GE(manager.fd(), 0);
    EXPECT_TRUE(manager.dispatch(0.0).empty());
    EXPECT_TRUE(capture.lines().empty());  // an empty directory is fine and quiet

    create("event7");
    create("mouse0");  // not an event node: never opened
    EXPECT_TRUE(manager.dispatch(0.0).empty());
    std::vector<std::string> lines = capture.lines();
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_TRUE(mentions(lines[0], path("event7"))) << lines[0];
    EXPECT_TRUE(mentions(lines[0], "not an evdev device")) << lines[0];
    EXPECT_EQ(lines[0].rfind("<4>gemkiosk: ", 0), 0u) << lines[0];
    EXPECT_EQ(opened, 1);
    EXPECT_EQ(closed, 1);  // what was opened and refused is closed through the closer
    EXPECT_TRUE(manager.open_devices().empty());

    // Its attributes change (as udev does): no second attempt, no second line.
    ASSERT_EQ(::chmod(path("event7").c_str(), 0640), 0);
    EXPECT_TRUE(manager.dispatch(0.0).empty());
    EXPECT_TRUE(capture.lines().empty());
    EXPECT_EQ(opened, 1);

    std::filesystem::remove(path("event7"));
    EXPECT_TRUE(manager.dispatch(0.0).empty());
    EXPECT_TRUE(capture.lines().empty());

    // A new node of the same name is a new device: tried and reported again.
    create("event7");
    manager.dispatch(0.0);
    EXPECT_EQ(capture.lines().size(), 1u);
    EXPECT_EQ(opened, 2);
}

TEST_F(InputManagerTest, PermissionFixedLaterIsRetriedOnAttrib) {
    StderrCapture capture;
    bool allowed = false;
    std::vector<std::string> attempts;
    InputManager manager(options(), [&](const std::string& p) {
        attempts.push_back(p);
        return allowed ? open_device_node(p) : -EACCES;
    });
    create("event3");
    manager.dispatch(0.0);
    // Refused at IN_CREATE: expected (udev has not set permissions yet), so not logged.
    EXPECT_EQ(attempts.size(), 1u);
    EXPECT_TRUE(capture.lines().empty());

    // udev changes the mode, still refused: tried again at once, quietly while it settles.
    ASSERT_EQ(::chmod(path("event3").c_str(), 0660), 0);
    manager.dispatch(0.05);
    EXPECT_EQ(attempts.size(), 2u);
    EXPECT_TRUE(capture.lines().empty());
    // Refused for longer than a node takes to settle: logged, once, with the errno text.
    manager.dispatch(InputManager::kSettleS + 0.1);
    EXPECT_EQ(attempts.size(), 3u);
    std::vector<std::string> lines = capture.lines();
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_TRUE(mentions(lines[0], path("event3"))) << lines[0];
    EXPECT_TRUE(mentions(lines[0], std::strerror(EACCES))) << lines[0];
    ASSERT_EQ(::chmod(path("event3").c_str(), 0640), 0);
    manager.dispatch(InputManager::kSettleS + 0.2);
    EXPECT_EQ(attempts.size(), 4u);
    EXPECT_TRUE(capture.lines().empty());

    // Allowed at last: opened (and then refused as not an evdev device, logged once).
    allowed = true;
    ASSERT_EQ(::chmod(path("event3").c_str(), 0644), 0);
    manager.dispatch(InputManager::kSettleS + 0.3);
    EXPECT_EQ(attempts.size(), 5u);
    lines = capture.lines();
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_TRUE(mentions(lines[0], "not an evdev device")) << lines[0];
}

// A node plugged in that its seat refuses for a moment (logind has not taken it yet) is
// opened by a retry, with nothing logged; the kiosk's loop is told when to retry.
TEST_F(InputManagerTest, ANodeRefusedForAMomentIsOpenedByARetryQuietly) {
    StderrCapture capture;
    int refusals = 2;
    std::vector<double> attempts;
    double now = 10.0;
    InputManager manager(options(), [&](const std::string& p) {
        attempts.push_back(now);
        return refusals-- > 0 ? -EAGAIN : open_device_node(p);
    });
    EXPECT_EQ(manager.next_retry_s(), std::numeric_limits<double>::infinity());
    create("event6");
    ASSERT_EQ(::chmod(path("event6").c_str(), 0660), 0);  // IN_CREATE and IN_ATTRIB at once
    manager.dispatch(now);
    EXPECT_EQ(attempts.size(), 2u);
    EXPECT_NEAR(manager.next_retry_s(), now + InputManager::kRetryS, 1e-9);
    // The loop dispatches more often than it retries (every frame, or every input event):
    // the retry comes all the same, when it is due.
    const double due = manager.next_retry_s();
    while (attempts.size() < 3u && now < due + 0.05) {
        now += 0.02;
        manager.dispatch(now);
        if (now < due) {
            EXPECT_EQ(attempts.size(), 2u) << "retried too soon, at " << now;
        }
    }
    ASSERT_EQ(attempts.size(), 3u);  // opened, and refused as not an evdev device
    const std::vector<std::string> lines = capture.lines();
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_TRUE(mentions(lines[0], "not an evdev device")) << lines[0];
    EXPECT_EQ(manager.next_retry_s(), std::numeric_limits<double>::infinity());
}

TEST_F(InputManagerTest, ANodeUnpluggedAsItIsOpenedIsNotAFault) {
    // udev's last change to a node can arrive after the device is gone: the open fails
    // because the device went, which is the unplugging, not a fault to warn about.
    StderrCapture capture;
    bool unplug_on_open = false;
    InputManager manager(options(), [&](const std::string& p) {
        if (!unplug_on_open) return -EACCES;
        std::filesystem::remove(p);
        return -ENODEV;
    });
    create("event4");
    manager.dispatch(0.0);
    unplug_on_open = true;
    ASSERT_EQ(::chmod(path("event4").c_str(), 0660), 0);
    manager.dispatch(0.0);
    EXPECT_TRUE(capture.lines().empty()) << capture.lines().front();
    EXPECT_TRUE(manager.open_devices().empty());
}

TEST_F(InputManagerTest, ExistingNodesAreScannedAtStart) {
    create("event1");
    create("event2");
    StderrCapture capture;
    std::vector<std::string> attempts;
    InputManager manager(options(), [&](const std::string& p) {
        attempts.push_back(p);
        return -ENOENT;
    });
    EXPECT_EQ(attempts, (std::vector<std::string>{path("event1"), path("event2")}));
    EXPECT_EQ(capture.lines().size(), 2u);  // one line per device that cannot be opened
}

TEST_F(InputManagerTest, OnlyTheListedDevices) {
    create("event1");
    create("event2");
    InputOptions o = options();
    o.devices = {path("event2")};
    std::vector<std::string> attempts;
    StderrCapture capture;
    InputManager manager(o, [&](const std::string& p) {
        attempts.push_back(p);
        return -ENOENT;
    });
    create("event5");  // not listed: ignored on hotplug too
    manager.dispatch(0.0);
    EXPECT_EQ(attempts, (std::vector<std::string>{path("event2")}));
}

TEST_F(InputManagerTest, MissingDirectoryIsOneLineAndTheKioskGoesOn) {
    StderrCapture capture;
    InputOptions o = options();
    o.device_dir = path("no-such-dir");
    InputManager manager(o);
    const std::vector<std::string> lines = capture.lines();
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_TRUE(mentions(lines[0], path("no-such-dir"))) << lines[0];
    EXPECT_TRUE(mentions(lines[0], std::strerror(ENOENT))) << lines[0];
    EXPECT_GE(manager.fd(), 0);
    EXPECT_TRUE(manager.dispatch(0.0).empty());
    EXPECT_TRUE(manager.open_devices().empty());
}

}  // namespace
}  // namespace gem::kiosk

// Device classification and the mouse-as-a-finger path, on hand-made capabilities and events.

#include <gtest/gtest.h>

#include "event_builders.hpp"
#include "input/device_decoder.hpp"
#include "input/device_kind.hpp"
#include "input/pointer_tracker.hpp"

namespace gem::kiosk {
namespace {

using test::ev;
using test::syn;

TEST(DeviceKind, Classification) {
    DeviceCapabilities atmel;  // as the Atmel maXTouch description declares
    atmel.direct = atmel.mt_position = atmel.mt_slot = atmel.abs_xy = atmel.btn_touch = true;
    EXPECT_EQ(classify(atmel), DeviceKind::touchscreen);

    DeviceCapabilities ntrig;  // N-Trig: no INPUT_PROP_DIRECT in its description, BTN_TOUCH
    ntrig.mt_position = ntrig.abs_xy = ntrig.btn_touch = true;
    EXPECT_EQ(classify(ntrig), DeviceKind::touchscreen);

    DeviceCapabilities mouse;
    mouse.rel_xy = mouse.btn_left = true;
    EXPECT_EQ(classify(mouse), DeviceKind::pointer);

    // QEMU's usb-tablet (tests/fixtures/kiosk/qemu-usb-tablet.desc), and touch controllers in
    // mouse mode: absolute axes and a left button, neither INPUT_PROP_DIRECT nor BTN_TOUCH.
    DeviceCapabilities tablet;
    tablet.abs_xy = tablet.btn_left = true;
    EXPECT_EQ(classify(tablet), DeviceKind::absolute_pointer);
    // A mouse that also reports absolute axes moves relatively.
    tablet.rel_xy = true;
    EXPECT_EQ(classify(tablet), DeviceKind::pointer);

    DeviceCapabilities keyboard;
    keyboard.typing_keys = true;
    EXPECT_EQ(classify(keyboard), DeviceKind::keyboard);

    DeviceCapabilities power_button;  // keys, but not typing ones
    EXPECT_EQ(classify(power_button), DeviceKind::other);

    DeviceCapabilities joystick;  // absolute axes without touch or INPUT_PROP_DIRECT
    joystick.abs_xy = true;
    EXPECT_EQ(classify(joystick), DeviceKind::other);
}

TEST(DeviceKind, TouchAxesPickTheProtocol) {
    DeviceCapabilities c;
    c.mt_position = c.mt_slot = c.abs_xy = c.btn_touch = true;
    c.mt_x = {0, 799};
    c.mt_y = {0, 479};
    c.abs_x = {0, 1};
    c.slot_maximum = 9;
    TouchAxes axes = touch_axes(c);
    EXPECT_EQ(axes.protocol, TouchProtocol::multitouch_b);
    EXPECT_EQ(axes.slot_count, 10);
    EXPECT_EQ(axes.x.maximum, 799);
    EXPECT_EQ(axes.y.maximum, 479);
    c.mt_slot = false;
    EXPECT_EQ(touch_axes(c).protocol, TouchProtocol::multitouch_a);
    c.mt_position = false;
    axes = touch_axes(c);
    EXPECT_EQ(axes.protocol, TouchProtocol::single_touch);
    EXPECT_EQ(axes.x.maximum, 1);
    EXPECT_EQ(axes.contact_key, BTN_TOUCH);
    // An absolute pointer: the left button is the finger.
    c.btn_touch = false;
    c.btn_left = true;
    EXPECT_EQ(touch_axes(c).contact_key, BTN_LEFT);
}

TEST(PointerTracker, LeftButtonIsOneFingerWheelIsZoom) {
    const glm::dvec2 picture{800, 600};
    PointerTracker pointer(picture);
    std::vector<InputEvent> out;
    // Moving without the button: nothing for the gestures.
    pointer.feed(ev(EV_REL, REL_X, 10), picture, out);
    pointer.feed(syn(1.0), picture, out);
    EXPECT_TRUE(out.empty());
    // Pressed at the centre (400, 300) plus the 10 px moved.
    pointer.feed(ev(EV_KEY, BTN_LEFT, 1), picture, out);
    pointer.feed(syn(2.0), picture, out);
    ASSERT_EQ(out.size(), 1u);
    const auto& pressed = std::get<TouchFrame>(out[0]);
    EXPECT_DOUBLE_EQ(pressed.time_s, 2.0);
    ASSERT_EQ(pressed.contacts.size(), 1u);
    EXPECT_EQ(pressed.contacts[0].position, glm::dvec2(410, 300));
    // Dragged far right and up: clamped to the picture's edge.
    pointer.feed(ev(EV_REL, REL_X, 5000), picture, out);
    pointer.feed(ev(EV_REL, REL_Y, -50), picture, out);
    pointer.feed(syn(3.0), picture, out);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(std::get<TouchFrame>(out[1]).contacts.at(0).position, glm::dvec2(800, 250));
    // Released: an empty frame.
    pointer.feed(ev(EV_KEY, BTN_LEFT, 0), picture, out);
    pointer.feed(syn(4.0), picture, out);
    ASSERT_EQ(out.size(), 3u);
    EXPECT_TRUE(std::get<TouchFrame>(out[2]).contacts.empty());
    // Two notches towards the user.
    pointer.feed(ev(EV_REL, REL_WHEEL, -2), picture, out);
    pointer.feed(syn(5.0), picture, out);
    ASSERT_EQ(out.size(), 4u);
    const auto& wheel = std::get<WheelStep>(out[3]);
    EXPECT_DOUBLE_EQ(wheel.steps, -2.0);
    EXPECT_EQ(wheel.position, glm::dvec2(800, 250));
}

TEST(DeviceDecoder, KeyboardsGiveNothing) {
    DeviceDecoder decoder(DeviceKind::keyboard, {});
    std::vector<InputEvent> out;
    const auto no_state = [] { return TouchSnapshot{}; };
    decoder.feed(ev(EV_KEY, KEY_A, 1), TouchMapping(), no_state, out);
    decoder.feed(syn(), TouchMapping(), no_state, out);
    EXPECT_TRUE(out.empty());
}

TEST(DeviceDecoder, TouchFramesAreMappedToThePicture) {
    DeviceDecoder decoder(DeviceKind::touchscreen,
                          {TouchProtocol::single_touch, {0, 100}, {0, 100}, 1});
    std::vector<InputEvent> out;
    const auto no_state = [] { return TouchSnapshot{}; };
    // Rotation 90 on a 480x800 picture: native (0.25, 0) -> (0, 600) (touch_mapping_test).
    const TouchMapping mapping(identity_calibration, 90, {480, 800});
    for (const input_event& e :
         {ev(EV_KEY, BTN_TOUCH, 1), ev(EV_ABS, ABS_X, 25), ev(EV_ABS, ABS_Y, 0), syn(7.5)})
        decoder.feed(e, mapping, no_state, out);
    ASSERT_EQ(out.size(), 1u);
    const auto& frame = std::get<TouchFrame>(out[0]);
    EXPECT_DOUBLE_EQ(frame.time_s, 7.5);
    ASSERT_EQ(frame.contacts.size(), 1u);
    EXPECT_NEAR(frame.contacts[0].position.x, 0.0, 1e-9);
    EXPECT_NEAR(frame.contacts[0].position.y, 600.0, 1e-9);
}

TEST(DeviceDecoder, AnAbsolutePointersButtonIsTheFinger) {
    DeviceCapabilities tablet;  // QEMU's usb-tablet: both axes 0..32767
    tablet.abs_xy = tablet.btn_left = true;
    tablet.abs_x = tablet.abs_y = {0, 32767};
    DeviceDecoder decoder(classify(tablet), touch_axes(tablet));
    const TouchMapping mapping(identity_calibration, 0, {640, 480});
    std::vector<InputEvent> out;
    TouchSnapshot state;
    const auto device_state = [&state] { return state; };
    // Hovering (moving without the button) is no touch.
    for (const input_event& e : {ev(EV_ABS, ABS_X, 8192), ev(EV_ABS, ABS_Y, 8192), syn(1.0)})
        decoder.feed(e, mapping, device_state, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_TRUE(std::get<TouchFrame>(out[0]).contacts.empty());
    // Pressed, then moved: one finger at 8192/32767 and 16384/32767 of the picture.
    for (const input_event& e : {ev(EV_KEY, BTN_LEFT, 1), syn(2.0), ev(EV_ABS, ABS_X, 16384),
                                 ev(EV_ABS, ABS_Y, 16384), syn(3.0)})
        decoder.feed(e, mapping, device_state, out);
    ASSERT_EQ(out.size(), 3u);
    const auto& pressed = std::get<TouchFrame>(out[1]).contacts;
    ASSERT_EQ(pressed.size(), 1u);
    EXPECT_NEAR(pressed[0].position.x, 640.0 * 8192.0 / 32767.0, 1e-9);
    EXPECT_NEAR(pressed[0].position.y, 480.0 * 8192.0 / 32767.0, 1e-9);
    const auto& moved = std::get<TouchFrame>(out[2]).contacts;
    ASSERT_EQ(moved.size(), 1u);
    EXPECT_NEAR(moved[0].position.x, 640.0 * 16384.0 / 32767.0, 1e-9);
    // Events lost while the button was let go: the device's state says it is up.
    state.left_button = false;
    state.touching = true;  // BTN_TOUCH's state is not this device's finger
    for (const input_event& e : {ev(EV_SYN, SYN_DROPPED, 0), syn(4.0)})
        decoder.feed(e, mapping, device_state, out);
    ASSERT_EQ(out.size(), 4u);
    EXPECT_TRUE(std::get<TouchFrame>(out[3]).contacts.empty());
}

}  // namespace
}  // namespace gem::kiosk

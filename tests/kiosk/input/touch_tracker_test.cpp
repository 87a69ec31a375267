// TouchTracker on hand-written event lists whose answers are worked out by hand, following
// Documentation/input/multi-touch-protocol.rst and event-codes.rst.

#include "input/touch_tracker.hpp"

#include <gtest/gtest.h>

#include <initializer_list>

#include "event_builders.hpp"

namespace gem::kiosk {
namespace {

using test::abs;
using test::dropped;
using test::key;
using test::mt_report;
using test::syn;

// Feeds events; returns the result of the last one.
FeedResult feed_all(TouchTracker& tracker, std::initializer_list<input_event> events) {
    FeedResult last = FeedResult::none;
    for (const input_event& event : events) last = tracker.feed(event);
    return last;
}

void expect_contact(const NormalisedContact& contact, int id, double x, double y) {
    EXPECT_EQ(contact.id, id);
    EXPECT_DOUBLE_EQ(contact.position.x, x);
    EXPECT_DOUBLE_EQ(contact.position.y, y);
}

TouchAxes protocol_b_axes() {
    return {TouchProtocol::multitouch_b, {0, 1000}, {0, 500}, 4};
}

TEST(TouchTrackerProtocolB, SlotsComeMoveAndGo) {
    TouchTracker tracker(protocol_b_axes());
    // Slot 0 is current until ABS_MT_SLOT says otherwise.
    EXPECT_EQ(feed_all(tracker, {abs(ABS_MT_TRACKING_ID, 10), abs(ABS_MT_POSITION_X, 100),
                                 abs(ABS_MT_POSITION_Y, 50), key(BTN_TOUCH, 1), syn()}),
              FeedResult::frame);
    ASSERT_EQ(tracker.contacts().size(), 1u);
    expect_contact(tracker.contacts()[0], 10, 0.1, 0.1);

    feed_all(tracker, {abs(ABS_MT_SLOT, 1), abs(ABS_MT_TRACKING_ID, 11),
                       abs(ABS_MT_POSITION_X, 500), abs(ABS_MT_POSITION_Y, 250), syn()});
    ASSERT_EQ(tracker.contacts().size(), 2u);
    expect_contact(tracker.contacts()[0], 10, 0.1, 0.1);
    expect_contact(tracker.contacts()[1], 11, 0.5, 0.5);

    // Only changes are sent: slot 0's y stays 50.
    feed_all(tracker, {abs(ABS_MT_SLOT, 0), abs(ABS_MT_POSITION_X, 200), syn()});
    ASSERT_EQ(tracker.contacts().size(), 2u);
    expect_contact(tracker.contacts()[0], 10, 0.2, 0.1);

    feed_all(tracker, {abs(ABS_MT_TRACKING_ID, -1), syn()});
    ASSERT_EQ(tracker.contacts().size(), 1u);
    expect_contact(tracker.contacts()[0], 11, 0.5, 0.5);

    feed_all(tracker, {abs(ABS_MT_SLOT, 1), abs(ABS_MT_TRACKING_ID, -1), key(BTN_TOUCH, 0), syn()});
    EXPECT_TRUE(tracker.contacts().empty());
}

TEST(TouchTrackerProtocolB, NothingBeforeTheFrameEnds) {
    TouchTracker tracker(protocol_b_axes());
    EXPECT_EQ(feed_all(tracker, {abs(ABS_MT_TRACKING_ID, 3), abs(ABS_MT_POSITION_X, 100)}),
              FeedResult::none);
    EXPECT_TRUE(tracker.contacts().empty());
}

TEST(TouchTrackerProtocolB, SynDroppedDiscardsThenResynchronises) {
    TouchTracker tracker(protocol_b_axes());
    feed_all(tracker, {abs(ABS_MT_TRACKING_ID, 10), abs(ABS_MT_POSITION_X, 100),
                       abs(ABS_MT_POSITION_Y, 50), syn()});
    // After SYN_DROPPED everything up to and including the next SYN_REPORT is ignored.
    EXPECT_EQ(feed_all(tracker, {dropped(), abs(ABS_MT_POSITION_X, 999)}), FeedResult::none);
    EXPECT_EQ(tracker.feed(syn()), FeedResult::resync_needed);
    ASSERT_EQ(tracker.contacts().size(), 1u);
    expect_contact(tracker.contacts()[0], 10, 0.1, 0.1);  // the ignored x = 999 did not land

    // The device meanwhile: finger 10 lifted, finger 12 down in slot 2, slot 2 current.
    TouchSnapshot snapshot;
    snapshot.slots.resize(4);
    snapshot.slots[2] = {12, 250, 125};
    snapshot.current_slot = 2;
    tracker.resynchronise(snapshot);
    ASSERT_EQ(tracker.contacts().size(), 1u);
    expect_contact(tracker.contacts()[0], 12, 0.25, 0.25);

    // Later events go to the snapshot's current slot.
    feed_all(tracker, {abs(ABS_MT_POSITION_X, 750), syn()});
    ASSERT_EQ(tracker.contacts().size(), 1u);
    expect_contact(tracker.contacts()[0], 12, 0.75, 0.25);
}

TEST(TouchTrackerProtocolA, ContactsByOrderAndEmptyFrames) {
    TouchTracker tracker({TouchProtocol::multitouch_a, {0, 100}, {0, 100}, 1});
    feed_all(tracker, {abs(ABS_MT_POSITION_X, 10), abs(ABS_MT_POSITION_Y, 20), mt_report(),
                       abs(ABS_MT_POSITION_X, 30), abs(ABS_MT_POSITION_Y, 40), mt_report(),
                       key(BTN_TOUCH, 1), syn()});
    ASSERT_EQ(tracker.contacts().size(), 2u);
    expect_contact(tracker.contacts()[0], 0, 0.1, 0.2);
    expect_contact(tracker.contacts()[1], 1, 0.3, 0.4);

    // Every frame repeats every contact: one contact now.
    feed_all(tracker, {abs(ABS_MT_POSITION_X, 50), abs(ABS_MT_POSITION_Y, 60), mt_report(), syn()});
    ASSERT_EQ(tracker.contacts().size(), 1u);
    expect_contact(tracker.contacts()[0], 0, 0.5, 0.6);

    // A lone SYN_MT_REPORT, and a frame with nothing at all: every finger lifted.
    feed_all(tracker, {mt_report(), syn()});
    EXPECT_TRUE(tracker.contacts().empty());
    feed_all(tracker, {abs(ABS_MT_POSITION_X, 50), abs(ABS_MT_POSITION_Y, 60), mt_report(), syn()});
    ASSERT_EQ(tracker.contacts().size(), 1u);
    feed_all(tracker, {key(BTN_TOUCH, 0), syn()});
    EXPECT_TRUE(tracker.contacts().empty());
}

TEST(TouchTrackerProtocolA, TrackingIdsWhenSent) {
    TouchTracker tracker({TouchProtocol::multitouch_a, {0, 100}, {0, 100}, 1});
    feed_all(tracker, {abs(ABS_MT_TRACKING_ID, 40), abs(ABS_MT_POSITION_X, 10),
                       abs(ABS_MT_POSITION_Y, 20), mt_report(), abs(ABS_MT_TRACKING_ID, 41),
                       abs(ABS_MT_POSITION_X, 90), abs(ABS_MT_POSITION_Y, 80), mt_report(), syn()});
    ASSERT_EQ(tracker.contacts().size(), 2u);
    expect_contact(tracker.contacts()[0], 40, 0.1, 0.2);
    expect_contact(tracker.contacts()[1], 41, 0.9, 0.8);
}

TEST(TouchTrackerProtocolA, SingleTouchEmulationIsIgnored) {
    // Protocol A drivers also send ABS_X/ABS_Y for old clients; only the MT axes count.
    TouchTracker tracker({TouchProtocol::multitouch_a, {0, 100}, {0, 100}, 1});
    feed_all(tracker, {abs(ABS_X, 99), abs(ABS_Y, 99), abs(ABS_MT_POSITION_X, 10),
                       abs(ABS_MT_POSITION_Y, 20), mt_report(), syn()});
    ASSERT_EQ(tracker.contacts().size(), 1u);
    expect_contact(tracker.contacts()[0], 0, 0.1, 0.2);
}

TEST(TouchTrackerSingleTouch, FollowsBtnTouch) {
    TouchTracker tracker({TouchProtocol::single_touch, {0, 200}, {0, 100}, 1});
    feed_all(tracker, {abs(ABS_X, 50), abs(ABS_Y, 25), syn()});
    EXPECT_TRUE(tracker.contacts().empty());  // hovering, not touching
    feed_all(tracker, {key(BTN_TOUCH, 1), syn()});
    ASSERT_EQ(tracker.contacts().size(), 1u);
    expect_contact(tracker.contacts()[0], 0, 0.25, 0.25);
    feed_all(tracker, {abs(ABS_X, 100), syn()});
    ASSERT_EQ(tracker.contacts().size(), 1u);
    expect_contact(tracker.contacts()[0], 0, 0.5, 0.25);
    feed_all(tracker, {key(BTN_TOUCH, 0), syn()});
    EXPECT_TRUE(tracker.contacts().empty());
}

TEST(TouchTrackerSingleTouch, ResynchronisesFromSnapshot) {
    TouchTracker tracker({TouchProtocol::single_touch, {0, 200}, {0, 100}, 1});
    feed_all(tracker, {key(BTN_TOUCH, 1), abs(ABS_X, 50), abs(ABS_Y, 25), syn()});
    EXPECT_EQ(feed_all(tracker, {dropped(), key(BTN_TOUCH, 0), syn()}), FeedResult::resync_needed);
    TouchSnapshot snapshot;
    snapshot.touching = true;
    snapshot.x = 150;
    snapshot.y = 75;
    tracker.resynchronise(snapshot);
    ASSERT_EQ(tracker.contacts().size(), 1u);
    expect_contact(tracker.contacts()[0], 0, 0.75, 0.75);
}

TEST(TouchTracker, NormalisesOnTheAxisRangeAndClamps) {
    // A range that starts below zero: -100 is 0, 0 is the middle, 100 is 1.
    TouchTracker tracker({TouchProtocol::single_touch, {-100, 100}, {-50, 150}, 1});
    feed_all(tracker, {key(BTN_TOUCH, 1), abs(ABS_X, 0), abs(ABS_Y, 100), syn()});
    ASSERT_EQ(tracker.contacts().size(), 1u);
    expect_contact(tracker.contacts()[0], 0, 0.5, 0.75);
    feed_all(tracker, {abs(ABS_X, 300), abs(ABS_Y, -80), syn()});
    expect_contact(tracker.contacts()[0], 0, 1.0, 0.0);
}

}  // namespace
}  // namespace gem::kiosk

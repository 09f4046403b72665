// FrameWorker (app/gui/platform/frame/frame_worker.h): the second thread of the pipelined frame
// loop. Its jobs run on another thread, one at a time and in order; wait() hands back what the job
// touched and rethrows what it threw; the worker is done with its job once destroyed.
#include "frame_worker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

TEST(FrameWorker, RunsTheJobOnAnotherThreadAndWaitHandsItsWorkBack) {
    FrameWorker worker;
    std::thread::id ran;
    int value = 0;
    worker.start([&] {
        ran = std::this_thread::get_id();
        value = 42;
    });
    worker.wait();
    EXPECT_EQ(value, 42);
    EXPECT_NE(ran, std::thread::id());
    EXPECT_NE(ran, std::this_thread::get_id());
}

TEST(FrameWorker, RunsJobsOneAtATimeInOrder) {
    FrameWorker worker;
    std::vector<int> order;
    std::atomic<int> running{0};
    int most = 0;
    for (int i = 0; i < 200; ++i) {
        worker.start([&, i] { // start() waits for the job before
            most = std::max(most, ++running);
            order.push_back(i);
            --running;
        });
    }
    worker.wait();
    ASSERT_EQ(order.size(), 200u);
    for (int i = 0; i < 200; ++i) EXPECT_EQ(order[static_cast<std::size_t>(i)], i);
    EXPECT_EQ(most, 1);
}

TEST(FrameWorker, WaitRethrowsWhatTheJobThrewAndTheWorkerGoesOn) {
    FrameWorker worker;
    worker.start([] { throw std::runtime_error("bad frame"); });
    EXPECT_THROW(worker.wait(), std::runtime_error);
    worker.wait(); // thrown once only
    int value = 0;
    worker.start([&] { value = 7; });
    worker.wait();
    EXPECT_EQ(value, 7);
}

TEST(FrameWorker, WaitWithNoJobReturnsAndDestroyingFinishesTheJob) {
    int value = 0;
    {
        FrameWorker worker;
        worker.wait();
        worker.start([&] { value = 3; });
    }
    EXPECT_EQ(value, 3);
}

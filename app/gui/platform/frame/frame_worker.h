// A second thread for the frame loop (prepared_frame.h): it prepares frame N+1 (the simulation,
// ImGui's NewFrame to Render, the scene's geometry: no GL call, no GLFW call) while the main
// thread issues frame N's GL calls. One job at a time; start() hands the app to the job, wait()
// hands it back: the two threads never touch the app together.
#pragma once

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

class FrameWorker {
  public:
    FrameWorker();
    ~FrameWorker(); // finishes the job started last
    FrameWorker(const FrameWorker&) = delete;
    FrameWorker& operator=(const FrameWorker&) = delete;

    // Runs `job` on the worker's thread (after the job before it); the caller must wait()
    // before it touches what `job` touches.
    void start(std::function<void()> job);
    // Waits for the job started last (returns at once when there is none); rethrows what it
    // threw.
    void wait();

  private:
    void loop();

    std::mutex mutex_;
    std::condition_variable changed_;
    std::function<void()> job_;
    bool busy_ = false, quit_ = false;
    std::exception_ptr error_;
    std::thread thread_; // last: started once the members above are ready
};

// PublishQueue: calls run on its own thread, in order, all of them, with bounded waiting.
#include "topics/publish_queue.h"

#include <gtest/gtest.h>
#include <pthread.h>

#include <atomic>
#include <cstdlib>
#include <chrono>
#include <future>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace bullet_sim_node {
namespace {

TEST(PublishQueue, RunsEveryCallInOrderOnItsOwnThread) {
  std::vector<int> order;
  std::vector<std::thread::id> threads;
  {
    PublishQueue queue(8);
    for (int i = 0; i < 1000; ++i) {
      queue.push([&order, &threads, i] {
        order.push_back(i);
        threads.push_back(std::this_thread::get_id());
      });
    }
    queue.flush();
    ASSERT_EQ(order.size(), 1000u);  // flush returned after the last call ran
  }
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(order[i], i);
  for (const std::thread::id& id : threads) {
    EXPECT_NE(id, std::this_thread::get_id());
    EXPECT_EQ(id, threads.front());
  }
}

TEST(PublishQueue, ItsThreadIsNamed) {
  PublishQueue queue;
  std::string name;
  queue.push([&name] {
    char buffer[16] = {};
    pthread_getname_np(pthread_self(), buffer, sizeof(buffer));
    name = buffer;
  });
  queue.flush();
  EXPECT_EQ(name, "sim_publish");
}

TEST(PublishQueue, DestructionSendsWhatIsQueued) {
  std::atomic<int> ran{0};
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  {
    PublishQueue queue(100);
    queue.push([released] { released.wait(); });  // holds the thread until all are queued
    for (int i = 0; i < 50; ++i) queue.push([&ran] { ++ran; });
    release.set_value();
  }
  EXPECT_EQ(ran.load(), 50);
}

TEST(PublishQueue, APushBeyondCapacityWaitsForTheThread) {
  std::promise<void> started, release;
  std::shared_future<void> released = release.get_future().share();
  PublishQueue queue(2);
  queue.push([&started, released] {
    started.set_value();
    released.wait();
  });
  started.get_future().wait();  // the thread has taken it and runs it
  queue.push([] {});
  queue.push([] {});  // the queue holds its capacity now
  std::atomic<bool> pushed{false};
  std::thread pusher([&] {
    queue.push([] {});
    pushed = true;
  });
  // The pusher cannot finish while the first call blocks the thread; once released, it must.
  for (int i = 0; i < 20 && !pushed; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_FALSE(pushed.load());
  release.set_value();
  pusher.join();
  EXPECT_TRUE(pushed.load());
  queue.flush();
}

TEST(PublishQueue, AThrowingCallDoesNotStopTheOthers) {
  std::atomic<int> ran{0};
  PublishQueue queue(4);
  queue.push([] { throw std::runtime_error("topic gone"); });
  queue.push([&ran] { ++ran; });
  queue.flush();
  EXPECT_EQ(ran.load(), 1);
}

using std::chrono::steady_clock;
constexpr auto kLongLinger = std::chrono::seconds(10);

/// Brings `queue` (of linger kLongLinger) into its lingering state: a push that comes
/// within a linger of the queue running dry leaves the thread lingering after it.
void startLingering(PublishQueue* queue, std::atomic<int>* ran) {
  for (int i = 0; i < 2; ++i) {
    queue->push([ran] { ++*ran; });
    queue->flush();
  }
}

TEST(PublishQueue, CallsPushedWhileTheThreadLingersLeaveTogetherAtItsEnd) {
  std::atomic<int> ran{0};
  PublishQueue queue(16, kLongLinger);
  startLingering(&queue, &ran);
  ASSERT_EQ(ran.load(), 2);
  // No wake-up per push: the thread looks again only when its linger ends.
  queue.push([&ran] { ++ran; });
  queue.push([&ran] { ++ran; });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(ran.load(), 2);
  // flush() does not wait for the linger.
  const auto start = steady_clock::now();
  queue.flush();
  EXPECT_EQ(ran.load(), 4);
  EXPECT_LT(steady_clock::now() - start, kLongLinger / 2);
}

TEST(PublishQueue, DestructionDoesNotWaitForTheLinger) {
  std::atomic<int> ran{0};
  steady_clock::time_point start;
  {
    PublishQueue queue(16, kLongLinger);
    startLingering(&queue, &ran);
    queue.push([&ran] { ++ran; });
    start = steady_clock::now();
  }
  EXPECT_LT(steady_clock::now() - start, kLongLinger / 2);
  EXPECT_EQ(ran.load(), 3);
}

TEST(PublishQueue, APushAfterTheQueueSatIdleLongerThanTheLingerRunsAtOnce) {
  PublishQueue queue(16, std::chrono::microseconds(1000));
  queue.push([] {});
  queue.flush();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the thread sleeps now
  std::promise<void> ran;
  queue.push([&ran] { ran.set_value(); });
  // Without flush: the push itself wakes the sleeping thread.
  EXPECT_EQ(ran.get_future().wait_for(std::chrono::seconds(5)), std::future_status::ready);
  queue.flush();
}

TEST(PublishQueue, WithoutALingerEveryPushWakesTheThread) {
  PublishQueue queue(16, std::chrono::microseconds(0));
  for (int i = 0; i < 3; ++i) {
    std::promise<void> ran;
    queue.push([&ran] { ran.set_value(); });
    EXPECT_EQ(ran.get_future().wait_for(std::chrono::seconds(5)), std::future_status::ready);
    queue.flush();
  }
}

/// Waits up to 5 s for `done`; a queue that never runs the call would hang the test
/// binary in the queue's destructor, so that ends it with a failure instead.
void expectSoon(std::future<void> done, const char* what) {
  if (done.wait_for(std::chrono::seconds(5)) == std::future_status::ready) return;
  ADD_FAILURE() << what << " did not happen within 5 s";
  std::abort();
}

/// A queue without a linger whose thread has gone to sleep on an empty queue.
void startSleeping(PublishQueue* queue) {
  queue->push([] {});
  queue->flush();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
}

TEST(PublishQueue, CallsPushedDuringABatchLeaveWhenItEnds) {
  PublishQueue queue(16, std::chrono::microseconds(0));
  startSleeping(&queue);
  std::atomic<int> ran{0};
  std::promise<void> last;
  {
    const PublishQueue::Batch batch(queue);
    queue.push([&ran] { ++ran; });
    queue.push([&ran] { ++ran; });
    queue.push([&ran, &last] {
      ++ran;
      last.set_value();
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_EQ(ran.load(), 0);  // the pushes did not wake the thread
  }
  // The batch's end did, without a flush.
  expectSoon(last.get_future(), "the batch's calls");
  EXPECT_EQ(ran.load(), 3);
  queue.flush();
}

TEST(PublishQueue, ABatchBeyondCapacityWakesTheThreadToMakeRoom) {
  PublishQueue queue(2, std::chrono::microseconds(0));
  startSleeping(&queue);
  std::atomic<int> ran{0};
  std::promise<void> pushed;
  std::thread pusher([&] {
    const PublishQueue::Batch batch(queue);
    for (int i = 0; i < 5; ++i) queue.push([&ran] { ++ran; });
    pushed.set_value();
  });
  expectSoon(pushed.get_future(), "five pushes into a queue of two within one batch");
  pusher.join();
  queue.flush();
  EXPECT_EQ(ran.load(), 5);
}

TEST(PublishQueue, FlushDuringABatchRunsWhatIsQueued) {
  PublishQueue queue(16, std::chrono::microseconds(0));
  startSleeping(&queue);
  std::atomic<int> ran{0};
  const PublishQueue::Batch batch(queue);
  queue.push([&ran] { ++ran; });
  std::promise<void> flushed;
  std::thread flusher([&] {
    queue.flush();
    flushed.set_value();
  });
  expectSoon(flushed.get_future(), "flush inside a batch");
  flusher.join();
  EXPECT_EQ(ran.load(), 1);
}

}  // namespace
}  // namespace bullet_sim_node

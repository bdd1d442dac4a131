// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/core/Parallel.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

#include "vv/core/Error.h"

namespace vv {

int workerCount() {
    if (const char* env = std::getenv("VV_THREADS")) {
        try {
            const int n = std::stoi(env);
            if (n >= 1) {
                return n;
            }
        } catch (const std::exception&) {
            // fall through to the hardware count
        }
    }
    return static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
}

namespace {

/// One parallelFor call: its chunks, taken by the calling thread and by the
/// pool's threads that join it, and the first error.
struct Job {
    const std::function<void(long, long)>* body = nullptr;
    const std::stop_token* stop = nullptr;
    long begin = 0;
    long end = 0;
    long grain = 1;
    long chunks = 0;
    std::atomic<long> next{0};
    std::atomic<bool> failed{false};
    std::atomic<bool> cancelled{false};
    std::mutex errorMutex;
    std::exception_ptr firstError;
    // guarded by the pool's mutex
    int seats = 0;                 ///< pool threads that may still join
    int active = 0;                ///< pool threads inside runChunks
    std::condition_variable left;  ///< notified when active drops to 0
};

/// Takes chunks of the job until none is left, it failed or it was stopped.
void runChunks(Job& job) {
    for (;;) {
        if (job.failed.load(std::memory_order_relaxed)) {
            return;
        }
        if (job.stop->stop_requested()) {
            job.cancelled = true;
            return;
        }
        const long chunk = job.next.fetch_add(1, std::memory_order_relaxed);
        if (chunk >= job.chunks) {
            return;
        }
        const long b = job.begin + chunk * job.grain;
        const long e = std::min(job.end, b + job.grain);
        try {
            (*job.body)(b, e);
        } catch (...) {
            const std::scoped_lock lock(job.errorMutex);
            if (!job.firstError) {
                job.firstError = std::current_exception();
            }
            job.failed = true;
            return;
        }
    }
}

/// Threads that live as long as the process and help the calling thread of
/// every parallelFor (starting a thread per call cost ~40 us, several times
/// per frame). The caller always takes chunks itself, so a job finishes even
/// when every pool thread is busy (nested calls, a forked child without the
/// threads); it waits only for the pool threads that joined it.
class Pool {
  public:
    static Pool& instance() {
        // never destroyed: its threads wait on it until the process ends
        // NOLINTNEXTLINE(*-owning-memory,*-non-const-global-variables)
        static auto* const pool = new Pool();
        return *pool;
    }

    void run(Job& job, int helpers) {
        if (helpers > 0) {
            {
                const std::scoped_lock lock(mutex_);
                while (threads_ < helpers) {
                    std::thread([this] { serve(); }).detach();
                    ++threads_;
                }
                job.seats = helpers;
                queue_.push_back(&job);
            }
            wake_.notify_all();
        }
        runChunks(job);
        if (helpers > 0) {
            std::unique_lock lock(mutex_);
            std::erase(queue_, &job);  // nobody joins from now on
            job.left.wait(lock, [&job] { return job.active == 0; });
        }
    }

  private:
    Pool() = default;

    void serve() {
        std::unique_lock lock(mutex_);
        for (;;) {
            wake_.wait(lock, [this] { return !queue_.empty(); });
            Job* job = queue_.front();
            ++job->active;
            if (--job->seats == 0) {
                queue_.pop_front();
            }
            lock.unlock();
            runChunks(*job);
            lock.lock();
            if (--job->active == 0) {
                job->left.notify_all();  // under the mutex: the job outlives this call
            }
        }
    }

    std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<Job*> queue_;
    int threads_ = 0;
};

}  // namespace

void parallelFor(long begin, long end, long grain, const std::function<void(long, long)>& body,
                 const std::stop_token& stop) {
    if (end <= begin) {
        return;
    }
    Job job;
    job.body = &body;
    job.stop = &stop;
    job.begin = begin;
    job.end = end;
    job.grain = std::max(1L, grain);
    job.chunks = (end - begin + job.grain - 1) / job.grain;
    const int threads = static_cast<int>(std::min<long>(workerCount(), job.chunks));
    Pool::instance().run(job, threads - 1);
    if (job.firstError) {
        std::rethrow_exception(job.firstError);
    }
    if (job.cancelled) {
        throw CancelledError();
    }
}

void parallelForTiles(int width, int height, int tileSize,
                      const std::function<void(const Tile&)>& body, const std::stop_token& stop) {
    if (width <= 0 || height <= 0) {
        return;
    }
    if (tileSize <= 0) {
        throw InvalidArgumentError("tile size must be positive");
    }
    const long tilesX = (width + tileSize - 1) / tileSize;
    const long tilesY = (height + tileSize - 1) / tileSize;
    parallelFor(
        0, tilesX * tilesY, 1,
        [&](long b, long e) {
            for (long i = b; i < e; ++i) {
                Tile t;
                t.x0 = static_cast<int>(i % tilesX) * tileSize;
                t.y0 = static_cast<int>(i / tilesX) * tileSize;
                t.x1 = std::min(width, t.x0 + tileSize);
                t.y1 = std::min(height, t.y0 + tileSize);
                body(t);
            }
        },
        stop);
}

}  // namespace vv

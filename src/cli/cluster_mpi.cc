// Copyright contactlaws authors.
//
// cluster.h with MPI. The first time a count of items is spread, the items
// go longest first by their expected cost (Expect), each to the rank with the
// least work so far, or in turn (item k to rank k mod ranks) when none is
// expected; every exchange then hands out every rank the seconds each item
// took, and the next spread of that count is planned from them alike (the
// cost of a trajectory changes little from one evaluation of a fit to the
// next). Every rank computes the same plan from the same costs: no message
// decides it.
// MPI_Init runs on a thread of its own, beside the command's reading and first
// items (the rank and ranks from the launcher's environment, checked later).
// Results are exchanged by two allgathers, so every rank holds every result
// and the reductions that follow run in item order on each: the same bits
// whatever the ranks and whoever computed what.

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "cli/cluster.h"
#include "cli/commands.h"
#include "ident/wire.h"
#include "contactlaws/contact_model.h"
#include "scene/number.h"

namespace contactlaws::cli {
namespace {

// How long rank 0 waits, once a stop came, for the ranks that have not
// reached an exchange, s: a stopped rank arrives within a step of a
// rollout; mpirun kills every rank 1 s after its SIGTERM
// (odls_base_sigkill_timeout), and rank 0 must name the missing ranks first.
constexpr double kGrace = 0.5;

// MPI's own thread: MPI_Init_thread and, once told, MPI_Finalize (the
// standard asks both of one thread). Between the two, the main thread makes
// every other call, one at a time (MPI_THREAD_SERIALIZED).
class MpiThread {
 public:
  void Start() {
    thread_ = std::thread([this] {
      int provided = 0;
      MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
      std::unique_lock<std::mutex> lock(mutex_);
      provided_ = provided;
      initialized_ = true;
      changed_.notify_all();
      changed_.wait(lock, [this] { return finalize_; });
      MPI_Finalize();
    });
  }
  // Waits for MPI_Init: the thread level MPI provides, or nothing when a
  // stop came (Ctrl-C, or mpirun ending the job because a rank died before
  // joining it) and MPI_Init had not returned kGrace later.
  std::optional<int> AwaitInit() {
    std::unique_lock<std::mutex> lock(mutex_);
    std::optional<std::chrono::steady_clock::time_point> stopped_at;
    const auto initialized = [this] { return initialized_; };
    while (!changed_.wait_for(lock, std::chrono::milliseconds(20), initialized)) {
      if (!stop_signal.load(std::memory_order_relaxed)) continue;
      const auto now = std::chrono::steady_clock::now();
      if (!stopped_at) stopped_at = now;
      if (now - *stopped_at > std::chrono::duration<double>(kGrace)) return std::nullopt;
    }
    return provided_;
  }
  void Finalize() {
    std::unique_lock<std::mutex> lock(mutex_);
    finalize_ = true;
    lock.unlock();
    changed_.notify_all();
    thread_.join();
  }

 private:
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool initialized_ = false;
  bool finalize_ = false;
  int provided_ = 0;
};

// This process's place in the job: its rank and the job's ranks, from the
// launcher's environment until MPI's own are checked against them, and MPI's
// thread. A process joins one job (MPI_Init runs once).
class Launch {
 public:
  // This rank, and the ranks when the launcher's environment gives them
  // beside it (srun's PMIx gives only the rank), as MPI_Init will; starts
  // MPI_Init on its own thread.
  explicit Launch(const char* rank_variable) : rank_variable_(rank_variable) {
    rank_ = static_cast<int>(
        ParseWholeNumber(std::getenv(rank_variable), 0, 1 << 30).value_or(-1));
    const char* sizes[][2] = {{"OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE"},
                              {"PMI_RANK", "PMI_SIZE"}};
    for (const auto& [r, s] : sizes) {
      if (std::string(r) != rank_variable || !std::getenv(s)) continue;
      size_variable_ = s;
      size_ = static_cast<int>(ParseWholeNumber(std::getenv(s), 1, 1 << 30).value_or(0));
    }
    thread_.Start();
  }

  // Waits for MPI_Init (on the main thread, before any other MPI call), and
  // ends the job in one line if MPI's world is not the launcher's. False
  // when the job was stopped before MPI_Init returned (MpiThread::AwaitInit).
  bool AwaitMpi() {
    if (ready_) return true;
    const std::optional<int> provided = thread_.AwaitInit();
    if (!provided) return false;
    ready_ = true;
    int mpi_rank = 0, mpi_size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &mpi_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &mpi_size);
    std::string wrong;
    if (*provided < MPI_THREAD_SERIALIZED) {
      wrong = fmt::format("MPI provides thread level {}, below MPI_THREAD_SERIALIZED (MPI_Init "
                          "runs on a thread of its own)", *provided);
    } else if (mpi_rank != rank_ || (size_variable_ && mpi_size != size_)) {
      wrong = fmt::format("the launcher gives rank {} of {} ({}), MPI rank {} of {}", rank_,
                          size_variable_ ? std::to_string(size_) : "?", rank_variable_,
                          mpi_rank, mpi_size);
    }
    if (!wrong.empty()) {
      // what every rank sees alike, rank 0 alone says
      if (mpi_rank == 0 || mpi_rank != rank_) fmt::print(stderr, "contactlaws: {}\n", wrong);
      std::fflush(stderr);
      MPI_Abort(MPI_COMM_WORLD, kExitRefused);
    }
    size_ = mpi_size;
    return true;
  }

  void Finalize() { thread_.Finalize(); }

  int rank() const { return rank_; }
  // known before any item is spread: from the launcher, or once MPI_Init
  // returned (ClusterSpread)
  int size() const { return size_; }
  bool launcher_gives_size() const { return size_variable_ != nullptr; }

 private:
  MpiThread thread_;
  const char* rank_variable_;
  const char* size_variable_ = nullptr;
  int rank_ = 0;
  int size_ = 0;  // 0 until known
  bool ready_ = false;  // MPI_Init returned and was checked
};

// Items as "1,3,5" (at most 20, then "...").
std::string ItemList(const std::vector<int>& items) {
  std::string text;
  for (size_t i = 0; i < items.size() && i < 20; ++i) {
    text += (i ? "," : "") + std::to_string(items[i]);
  }
  if (items.size() > 20) text += ",...";
  return text;
}

// What a rank spent, summed over the exchanges of the command, s.
struct Timing {
  double busy = 0;      // its items' CPU seconds
  double waiting = 0;   // for the last rank to reach the exchange
  double exchange = 0;  // in the allgathers themselves
  double exchanges = 0;
};

class MpiSpread final : public WorkSpread {
 public:
  explicit MpiSpread(Launch* launch) : launch_(launch) {}

  void Expect(const std::vector<double>& cost) override {
    const int count = static_cast<int>(cost.size());
    if (plans_.find(count) == plans_.end()) plans_[count] = LongestFirst(cost, Size());
  }

  bool Mine(int k, int count) const override { return Owner(k, count) == Rank(); }

  void Share(std::vector<std::string>* items, const std::vector<double>& seconds) override {
    const int count = static_cast<int>(items->size());
    if (!launch_->AwaitMpi()) {
      // rank 0 alone tells the job's end, and cannot know which ranks joined
      if (Rank() != 0) std::_Exit(kExitInterrupted);
      throw Error(Missing(count, nullptr));
    }
    // this rank's items, in item order, each with its seconds
    std::vector<std::pair<double, std::string>> items_mine;
    for (int k = 0; k < count; ++k) {
      if (!Mine(k, count)) continue;
      timing_.busy += seconds[k];
      items_mine.emplace_back(seconds[k], std::move((*items)[k]));
    }
    const std::string mine = internal::Written(items_mine);
    // the wait for the slowest rank apart from the exchange proper
    double start = MPI_Wtime();
    AwaitArrivals(count);
    MPI_Barrier(MPI_COMM_WORLD);
    timing_.waiting += MPI_Wtime() - start;
    start = MPI_Wtime();
    const int size = Size();
    std::vector<int> lengths(size), offsets(size);
    int length = static_cast<int>(mine.size());
    MPI_Allgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, MPI_COMM_WORLD);
    int total = 0;
    for (int r = 0; r < size; ++r) offsets[r] = total, total += lengths[r];
    std::string all(total, '\0');
    MPI_Allgatherv(mine.data(), length, MPI_BYTE, all.data(), lengths.data(), offsets.data(),
                   MPI_BYTE, MPI_COMM_WORLD);
    timing_.exchange += MPI_Wtime() - start;
    timing_.exchanges += 1;
    // each rank's items, in item order, as the plan that made them
    std::vector<std::vector<std::pair<double, std::string>>> from(size);
    for (int r = 0; r < size; ++r) {
      from[r] = internal::Read<std::vector<std::pair<double, std::string>>>(
          all.substr(offsets[r], lengths[r]));
    }
    std::vector<size_t> next(size, 0);
    std::vector<double> every(count);
    for (int k = 0; k < count; ++k) {
      std::pair<double, std::string>& item = from[Owner(k, count)][next[Owner(k, count)]++];
      every[k] = item.first;
      (*items)[k] = std::move(item.second);
    }
    plans_[count] = LongestFirst(every, size);
  }

  const Timing& timing() const { return timing_; }

 private:
  // Every rank tells rank 0 it reached the exchange. Once a stop came
  // (Ctrl-C, or mpirun ending the job because a rank died: both send
  // SIGTERM), rank 0 throws, naming the ranks still missing after kGrace and
  // the items they held, so that the command ends with that one line and
  // its unfinished files removed.
  void AwaitArrivals(int count) const {
    constexpr int kArrived = 23;  // the message's tag
    if (Rank() != 0) {
      MPI_Send(nullptr, 0, MPI_BYTE, 0, kArrived, MPI_COMM_WORLD);
      return;
    }
    const int size = Size();
    std::vector<MPI_Request> arrivals(size, MPI_REQUEST_NULL);
    for (int r = 1; r < size; ++r) {
      MPI_Irecv(nullptr, 0, MPI_BYTE, r, kArrived, MPI_COMM_WORLD, &arrivals[r]);
    }
    double stopped_at = -1;
    while (true) {
      int all = 0;
      MPI_Testall(size, arrivals.data(), &all, MPI_STATUSES_IGNORE);
      if (all) return;
      if (stop_signal.load(std::memory_order_relaxed)) {
        if (stopped_at < 0) stopped_at = MPI_Wtime();
        if (MPI_Wtime() - stopped_at > kGrace) {
          const std::string missing = Missing(count, &arrivals);
          if (!missing.empty()) throw Error(missing);
        }
      }
      std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
  }

  // "exchange 2: rank 1 (items 1,3 of 4) did not arrive ...", naming each
  // rank whose arrival is still pending (every other rank when the job was
  // stopped before MPI_Init returned: arrivals null); empty when none is.
  std::string Missing(int count, std::vector<MPI_Request>* arrivals) const {
    std::string ranks;
    for (int r = 1; r < Size(); ++r) {
      int arrived = 0;
      if (arrivals) MPI_Test(&(*arrivals)[r], &arrived, MPI_STATUS_IGNORE);
      if (arrived) continue;
      std::vector<int> held;
      for (int k = 0; k < count; ++k) {
        if (Owner(k, count) == r) held.push_back(k);
      }
      ranks += fmt::format("{}rank {} (items {} of {})", ranks.empty() ? "" : ", ", r,
                           ItemList(held), count);
    }
    if (ranks.empty()) return ranks;
    return fmt::format("exchange {}: {} did not arrive after the stop (died, or ended by "
                       "mpirun{}); items count from 0 in input order, nothing written",
                       static_cast<long>(timing_.exchanges) + 1, ranks,
                       arrivals ? "" : ", before MPI_Init returned");
  }

  int Owner(int k, int count) const {
    const auto plan = plans_.find(count);
    return plan == plans_.end() ? k % Size() : plan->second[k];
  }

  int Rank() const { return launch_->rank(); }
  int Size() const { return launch_->size(); }

  Launch* launch_;
  std::map<int, std::vector<int>> plans_;  // per count, each item's rank
  Timing timing_;
};

// The job this process joined: its launch, the spread of its work over the
// ranks, and what the timing line reports.
struct Job {
  explicit Job(const char* rank_variable) : launch(rank_variable) {}

  // Rank 0's timing line on stderr: every rank's times, gathered.
  void PrintTiming() {
    const Timing& mine = spread.timing();
    const double sent[4] = {mine.busy / threads_per_rank, mine.waiting, mine.exchange,
                            mine.exchanges};
    const int size = launch.size();
    std::vector<double> all(4 * size);
    MPI_Gather(sent, 4, MPI_DOUBLE, all.data(), 4, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    if (launch.rank() != 0) return;
    double busy_min = all[0], busy_max = all[0], busy_sum = 0, waiting = 0;
    for (int r = 0; r < size; ++r) {
      busy_min = std::min(busy_min, all[4 * r]);
      busy_max = std::max(busy_max, all[4 * r]);
      busy_sum += all[4 * r];
      waiting += all[4 * r + 1];
    }
    const double busy_mean = busy_sum / size;
    fmt::print(stderr,
               "contactlaws: timing: {} ranks x {} thread{}, wall {:.3f} s; busy (CPU) per rank "
               "min {:.3f} mean {:.3f} max {:.3f} s (max/mean {:.3f}); waiting for the slowest "
               "{:.3f} s (rank mean); exchange {:.6f} s in {} allgathers\n",
               size, threads_per_rank, threads_per_rank == 1 ? "" : "s",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - joined_at).count(),
               busy_min, busy_mean, busy_max, busy_mean > 0 ? busy_max / busy_mean : 1.0,
               waiting / size, all[2], static_cast<long>(all[3]));
  }

  const std::chrono::steady_clock::time_point joined_at = std::chrono::steady_clock::now();
  Launch launch;
  MpiSpread spread{&launch};
  bool spread_used = false;  // the command spread its work (and reports its timing)
  int threads_per_rank = 1;
};

// The process's job, once it joined one (launched as a rank); null otherwise.
std::unique_ptr<Job>& ThisJob() {
  static std::unique_ptr<Job> job;
  return job;
}

}  // namespace

bool JoinCluster() {
  // launched alone: the only process, without MPI's start-up
  const char* rank_variable = LauncherRankVariable();
  if (!rank_variable) return true;
  ThisJob() = std::make_unique<Job>(rank_variable);
  if (ThisJob()->launch.rank() != 0) std::freopen("/dev/null", "w", stdout);
  return true;
}

void SetThreadsPerRank(int jobs) {
  if (ThisJob()) ThisJob()->threads_per_rank = std::max(1, jobs);
}

void LeaveCluster(int exit_code) {
  Job* job = ThisJob().get();
  if (!job) return;
  if (!job->launch.AwaitMpi()) {
    // stopped before MPI_Init returned: no MPI call can end this rank
    std::fflush(stdout);
    std::fflush(stderr);
    std::_Exit(exit_code ? exit_code : kExitInterrupted);
  }
  // an incomplete or interrupted run is known to every rank alike (every
  // rank holds every result and status); any other failure may be this
  // rank's alone
  if (exit_code != 0 && exit_code != kExitIncomplete && exit_code != kExitInterrupted &&
      job->launch.size() > 1) {
    // the others may wait in an exchange this rank will never join
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, exit_code);
  }
  // no rank leaves before rank 0 has written: mpirun ends the job when a
  // rank exits non-zero
  MPI_Barrier(MPI_COMM_WORLD);
  if (job->spread_used) job->PrintTiming();
  job->launch.Finalize();
}

WorkSpread* ClusterSpread() {
  Job* job = ThisJob().get();
  if (!job) return nullptr;
  // the launcher does not say how many ranks
  if (!job->launch.launcher_gives_size() && !job->launch.AwaitMpi()) {
    throw Error("stopped before MPI_Init returned");
  }
  if (job->launch.size() == 1) return nullptr;
  job->spread_used = true;
  return &job->spread;
}

bool WritesOutputs() { return !ThisJob() || ThisJob()->launch.rank() == 0; }

}  // namespace contactlaws::cli

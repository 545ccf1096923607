// The MPI distributor, a module loaded only under mpirun (distribute_serial.cpp): a master-worker protocol on
// MPI_COMM_WORLD with one chunk index per request.
//   worker -> root  kReady (empty) twice, then kResult ("chunk\n" + result text) after each chunk: each asks for
//                   one more, so a worker always has its next chunk queued while it computes (the root answers
//                   only between its own placements)
//   root -> worker  kWork (the chunk index), kDone (no more chunks: finish the queued ones) or kStop (stopped
//                   early: a busy worker polls for it between placements and abandons its chunk)
//   worker -> root  kBye after kStop, its last message; the root returns when every worker has said it.
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <deque>
#include <string>

#include "solvers/design/distribute.h"

namespace contactcert::solvers {
namespace {

enum Tag { kReady = 1, kResult = 2, kWork = 3, kDone = 4, kStop = 5, kBye = 6 };

/// Ranks beyond which the root only serves requests (its own chunks would delay every worker's next chunk).
constexpr int kRootWorksBelow = 16;

std::string receive_text(const MPI_Status& probed) {
  int length = 0;
  MPI_Get_count(&probed, MPI_CHAR, &length);
  std::string text(static_cast<std::size_t>(length), '\0');
  MPI_Recv(text.data(), length, MPI_CHAR, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return text;
}

void send_text(const std::string& text, int to, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

class MpiDistributor : public Distributor {
 public:
  MpiDistributor() {
    MPI_Init(nullptr, nullptr);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiDistributor() override { MPI_Finalize(); }
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  std::string from_root(const std::string& text) override {
    long length = static_cast<long>(text.size());
    MPI_Bcast(&length, 1, MPI_LONG, 0, MPI_COMM_WORLD);
    std::string root(static_cast<std::size_t>(length), '\0');
    if (rank_ == 0) root = text;
    MPI_Bcast(root.data(), static_cast<int>(length), MPI_CHAR, 0, MPI_COMM_WORLD);
    return root;
  }
  void agree(const std::string& problem) override {
    const std::string root = from_root(problem);
    if (root != problem)
      abort_all("rank " + std::to_string(rank_) + " read another design problem than rank 0 (" + problem + " vs " +
                    root + "): every node needs the same scene and candidate files",
                2);
  }
  void abort_all(const std::string& message, int code) override {
    std::fprintf(stderr, "contactcert: %s\n", message.c_str());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, code);
  }

  bool run(const ChunkSource& next, const ChunkWork& work, const ChunkRecord& record,
           const std::function<bool()>& keep_going) override {
    if (rank_ != 0) return work_loop(work);
    next_ = &next;
    queue_.clear();
    stopping_ = false;
    outstanding_ = 0;
    byes_ = 0;
    stop_sent_.assign(static_cast<std::size_t>(size_), false);
    auto between = [&] {
      serve(record, keep_going, false);
      return !stopping_;
    };
    while (size_ < kRootWorksBelow && !stopping_ && has_work()) {
      const long chunk = queue_.front();
      queue_.pop_front();
      ++outstanding_;
      const std::optional<std::string> result = work(chunk, between);
      --outstanding_;
      if (result)
        record(chunk, *result);
      else
        queue_.push_front(chunk);
      if (!keep_going()) stop_unless_done();
    }
    while (byes_ < size_ - 1) serve(record, keep_going, true);
    return !stopping_ && !has_work() && outstanding_ == 0;
  }

 private:
  /// Worker side: ask, compute, answer, until kStop.
  bool work_loop(const ChunkWork& work) {
    send_text("", 0, kReady);
    send_text("", 0, kReady);
    int code = 0;
    for (;;) {  // in order: the queued kWork messages come before kDone
      MPI_Status st;
      MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &st);
      const std::string text = receive_text(st);
      if (st.MPI_TAG == kDone || st.MPI_TAG == kStop) {
        code = st.MPI_TAG == kDone ? 0 : 3;
        break;
      }
      const long chunk = std::atol(text.c_str());
      auto between = [] {
        int flag = 0;
        MPI_Iprobe(0, kStop, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE);
        return flag == 0;
      };
      const std::optional<std::string> result = work(chunk, between);
      if (!result) continue;  // the kStop that aborted it is received next
      send_text(std::to_string(chunk) + "\n" + *result, 0, kResult);
    }
    send_text("", 0, kBye);
    return code == 0;
  }

  /// Is a chunk left to hand out? The queue holds chunks given back (the root's own, abandoned between
  /// placements); the source the rest, taken one at a time.
  bool has_work() {
    if (queue_.empty())
      if (const std::optional<long> chunk = (*next_)()) queue_.push_back(*chunk);
    return !queue_.empty();
  }

  /// A budget reached: stop, unless its last chunk has just been recorded (then every rank ends with the result).
  void stop_unless_done() {
    if (outstanding_ > 0 || has_work()) stop_all();
  }

  void stop_all() {
    if (stopping_) return;
    stopping_ = true;
    for (int r = 1; r < size_; ++r)
      if (!stop_sent_[static_cast<std::size_t>(r)]) send_stop(r);
  }

  void send_stop(int r) {
    stop_sent_[static_cast<std::size_t>(r)] = true;
    send_text("", r, stopping_ ? kStop : kDone);
  }

  /// Root: answers every pending message (blocking for one when `wait`).
  void serve(const ChunkRecord& record, const std::function<bool()>& keep_going, bool wait) {
    for (;;) {
      MPI_Status st;
      int flag = 0;
      if (wait) {
        MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &st);
        flag = 1;
        wait = false;
      } else {
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
      }
      if (!flag) return;
      const std::string text = receive_text(st);
      const int from = st.MPI_SOURCE;
      if (st.MPI_TAG == kBye) {
        ++byes_;
        continue;
      }
      if (st.MPI_TAG == kResult) {
        const std::size_t nl = text.find('\n');
        --outstanding_;
        record(std::atol(text.substr(0, nl).c_str()), text.substr(nl + 1));
        if (!keep_going()) stop_unless_done();
      }
      if (stop_sent_[static_cast<std::size_t>(from)]) continue;
      if (stopping_ || !has_work()) {
        send_stop(from);
        continue;
      }
      ++outstanding_;
      send_text(std::to_string(queue_.front()), from, kWork);
      queue_.pop_front();
    }
  }

  int rank_ = 0, size_ = 1;
  const ChunkSource* next_ = nullptr;
  std::deque<long> queue_;
  std::vector<bool> stop_sent_;
  bool stopping_ = false;
  long outstanding_ = 0;
  int byes_ = 0;
};

}  // namespace

}  // namespace contactcert::solvers

/// The module's entry point, found by make_distributor under mpirun: a new MPI distributor (MPI initialised).
extern "C" contactcert::solvers::Distributor* contactcert_mpi_distributor() {
  return new contactcert::solvers::MpiDistributor();
}

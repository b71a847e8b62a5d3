#include "verification/sweep/mpi_session.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#ifndef STONESKIP_HAVE_MPI
#define STONESKIP_HAVE_MPI 0  // CMake defines it to 1 when it found MPI
#endif
#if STONESKIP_HAVE_MPI
#define OMPI_SKIP_MPICXX 1   // the C API only: no C++ bindings to link
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace stoneskip {

bool MpiSession::built_with_mpi() { return STONESKIP_HAVE_MPI != 0; }

bool MpiSession::launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(v)) return true;
  return false;
}

int MpiSession::launched_size() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* s = std::getenv(v)) return std::max(1, std::atoi(s));
  return 1;
}

#if STONESKIP_HAVE_MPI

struct MpiSession::Pending {
  std::vector<unsigned char> bytes;
  MPI_Request request = MPI_REQUEST_NULL;
};

namespace {
void check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}
}  // namespace

MpiSession::MpiSession() {
  if (!launched_by_mpi()) return;
  int provided = 0;
  check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  active_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  if (provided < MPI_THREAD_FUNNELED) {
    // Compute threads beside the MPI thread need FUNNELED; every MPI in use provides it.
    if (rank_ == 0) std::fprintf(stderr, "stoneskip: this MPI does not support MPI_THREAD_FUNNELED\n");
    MPI_Abort(MPI_COMM_WORLD, 3);
  }
}

MpiSession::~MpiSession() {
  if (!active_) return;
  try {
    flush();
  } catch (...) {
  }
  MPI_Finalize();
}

int MpiSession::first_failed_rank(bool ok) const {
  if (!active_) return ok ? -1 : 0;
  const int mine = ok ? size_ : rank_;
  int lowest = size_;
  check(MPI_Allreduce(&mine, &lowest, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD), "MPI_Allreduce");
  return lowest == size_ ? -1 : lowest;
}

void MpiSession::barrier() const {
  if (active_) check(MPI_Barrier(MPI_COMM_WORLD), "MPI_Barrier");
}

bool MpiSession::poll(int source, int tag, Message& m) const {
  int flag = 0;
  MPI_Status st;
  check(MPI_Iprobe(source < 0 ? MPI_ANY_SOURCE : source, tag < 0 ? MPI_ANY_TAG : tag, MPI_COMM_WORLD, &flag, &st),
        "MPI_Iprobe");
  if (!flag) return false;
  int count = 0;
  MPI_Get_count(&st, MPI_BYTE, &count);
  m.source = st.MPI_SOURCE;
  m.tag = st.MPI_TAG;
  m.bytes.resize(static_cast<std::size_t>(count));
  check(MPI_Recv(m.bytes.data(), count, MPI_BYTE, st.MPI_SOURCE, st.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
        "MPI_Recv");
  return true;
}

MpiSession::Message MpiSession::wait(int source, int tag, double sleep_s) const {
  Message m;
  const auto pause = std::chrono::duration<double>(sleep_s);
  while (!poll(source, tag, m)) std::this_thread::sleep_for(pause);
  return m;
}

void MpiSession::send(int dest, int tag, std::vector<unsigned char> bytes) {
  auto* p = new Pending{std::move(bytes), MPI_REQUEST_NULL};
  check(MPI_Isend(p->bytes.data(), static_cast<int>(p->bytes.size()), MPI_BYTE, dest, tag, MPI_COMM_WORLD, &p->request),
        "MPI_Isend");
  pending_.push_back(p);
  progress();
}

void MpiSession::progress() {
  for (auto it = pending_.begin(); it != pending_.end();) {
    int done = 0;
    check(MPI_Test(&(*it)->request, &done, MPI_STATUS_IGNORE), "MPI_Test");
    if (done) {
      delete *it;
      it = pending_.erase(it);
    } else {
      ++it;
    }
  }
}

void MpiSession::flush() {
  for (Pending* p : pending_) {
    MPI_Wait(&p->request, MPI_STATUS_IGNORE);
    delete p;
  }
  pending_.clear();
}

void MpiSession::abort(int code) const {
  if (active_) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

#else  // a lone process

struct MpiSession::Pending {};
MpiSession::MpiSession() = default;
MpiSession::~MpiSession() = default;
int MpiSession::first_failed_rank(bool ok) const { return ok ? -1 : 0; }
void MpiSession::barrier() const {}
bool MpiSession::poll(int, int, Message&) const { return false; }
MpiSession::Message MpiSession::wait(int, int, double) const {
  throw std::logic_error("MpiSession::wait without MPI");
}
void MpiSession::send(int, int, std::vector<unsigned char>) { throw std::logic_error("MpiSession::send without MPI"); }
void MpiSession::progress() {}
void MpiSession::flush() {}
void MpiSession::abort(int code) const { std::exit(code); }

#endif

}  // namespace stoneskip

#pragma once
// The process's place in an MPI job, and the few messages a sweep sends. Built against Open MPI
// when CMake found it (STONESKIP_HAVE_MPI); otherwise, or when the process was not started by an
// MPI launcher (mpirun, srun), it is a job of one process and never touches MPI.
//
// Only the thread that constructed the session calls MPI (MPI_THREAD_FUNNELED): compute threads
// never do. Messages are byte buffers between ranks of one homogeneous job.
#include <cstddef>
#include <string>
#include <vector>

namespace stoneskip {

class MpiSession {
 public:
  MpiSession();   // MPI_Init_thread when launched by an MPI launcher and built with MPI
  ~MpiSession();  // MPI_Finalize
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  bool active() const { return active_; }  // more than a lone process: MPI is initialised
  int rank() const { return rank_; }
  int size() const { return size_; }
  static bool built_with_mpi();
  // True when the environment shows an MPI launcher (Open MPI's mpirun, PMI/PMIx as under srun).
  static bool launched_by_mpi();
  // The job size the launcher announces (OMPI_COMM_WORLD_SIZE, PMI_SIZE), 1 when it says none.
  static int launched_size();

  // Collective: the lowest rank whose `ok` is false, or −1 when every rank is ok.
  int first_failed_rank(bool ok) const;
  // Collective: returns when every rank has called it.
  void barrier() const;

  // Point-to-point, bytes. poll() does not block; wait() blocks politely (probe and sleep, so a
  // waiting rank leaves its core to the compute threads).
  struct Message {
    int source = -1;
    int tag = -1;
    std::vector<unsigned char> bytes;
  };
  bool poll(int source, int tag, Message& m) const;  // source/tag < 0: any
  Message wait(int source, int tag, double sleep_s) const;
  // Non-blocking send: the buffer is kept until the send completes; progress() completes them.
  void send(int dest, int tag, std::vector<unsigned char> bytes);
  void progress();
  void flush();  // waits for every pending send
  [[noreturn]] void abort(int code) const;

 private:
  bool active_ = false;
  int rank_ = 0, size_ = 1;
  struct Pending;
  std::vector<Pending*> pending_;
};

}  // namespace stoneskip

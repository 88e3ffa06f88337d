#pragma once
// The few MPI calls a tiled decimation needs (app/setup/tile_jobs.h):
// OpenMPI's C interface, started only when mpirun started this process,
// so that triwalk run alone never touches MPI.

#include <array>

namespace triwalk {

// Whether mpirun (or srun with PMIx) started this process: its environment
// names a rank.
bool startedByMpirun();
// This process's rank as mpirun's environment names it (0 when not started
// by mpirun): known before MPI starts, so that only rank 0 reports.
int rankFromEnvironment();

// MPI_Init_thread (only the calling thread talks to MPI; TBB's threads
// compute) and MPI_Finalize when it goes.
class MpiWorld {
public:
  MpiWorld();
  ~MpiWorld();
  MpiWorld(const MpiWorld&) = delete;
  MpiWorld& operator=(const MpiWorld&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // The ranks on this machine (a tile's share of its memory).
  int localSize() const;

  // Rank 0's value, on every rank.
  int broadcast(int value) const;
  // Two ints to and from a rank; receive takes them from any rank and
  // returns the sender.
  void send(int to, std::array<int, 2> message) const;
  int receive(std::array<int, 2>& message) const;
  std::array<int, 2> receiveFrom(int from) const;

private:
  int rank_ = 0, size_ = 1;
};

}  // namespace triwalk

#include "app/setup/mpi_world.h"

#include "core/support/errors.h"

#include <mpi.h>

#include <cstdlib>
#include <string>

namespace triwalk {
namespace {

constexpr int kTag = 69;

}  // namespace

bool startedByMpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMIX_RANK") != nullptr ||
         std::getenv("PMI_RANK") != nullptr;
}

int rankFromEnvironment() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"}) {
    if (const char* value = std::getenv(name)) return std::atoi(value);
  }
  return 0;
}

MpiWorld::MpiWorld() {
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    throw InputError("mpirun", "MPI could not start");
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiWorld::~MpiWorld() { MPI_Finalize(); }

int MpiWorld::localSize() const {
  const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  const int count = local ? std::atoi(local) : 0;
  return count > 0 ? count : 1;
}

int MpiWorld::broadcast(int value) const {
  MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value;
}

void MpiWorld::send(int to, std::array<int, 2> message) const {
  MPI_Send(message.data(), 2, MPI_INT, to, kTag, MPI_COMM_WORLD);
}

int MpiWorld::receive(std::array<int, 2>& message) const {
  MPI_Status status;
  MPI_Recv(message.data(), 2, MPI_INT, MPI_ANY_SOURCE, kTag, MPI_COMM_WORLD, &status);
  return status.MPI_SOURCE;
}

std::array<int, 2> MpiWorld::receiveFrom(int from) const {
  std::array<int, 2> message{};
  MPI_Recv(message.data(), 2, MPI_INT, from, kTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return message;
}

}  // namespace triwalk

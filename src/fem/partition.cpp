#include "gradfric/fem/partition.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/petsc_handle.hpp"

#include <metis.h>

#include <stdexcept>

namespace gradfric::fem {

static_assert(sizeof(idx_t) == sizeof(PetscInt), "METIS idx_t and PetscInt must have the same width");

namespace {

std::vector<PetscInt> metisOwners(DM serial, int nparts) {
  PetscInt nv = 0;
  PetscInt *xadj = nullptr, *adjncy = nullptr;
  OwnedIS numbering;
  GF_CALL(DMPlexCreatePartitionerGraph(serial, 0, &nv, &xadj, &adjncy, numbering.out()));
  std::vector<PetscInt> owner(nv, 0);
  if (nv > 0 && nparts > 1) {
    idx_t n = nv, ncon = 1, np = nparts, cut = 0;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    options[METIS_OPTION_SEED] = 12345;  // deterministic partition
    std::vector<idx_t> part(nv);
    const int status = METIS_PartGraphKway(&n, &ncon, reinterpret_cast<idx_t*>(xadj), reinterpret_cast<idx_t*>(adjncy),
                                           nullptr, nullptr, nullptr, &np, nullptr, nullptr, options, &cut,
                                           part.data());
    if (status != METIS_OK) {
      PetscFree(xadj);
      PetscFree(adjncy);
      throw std::runtime_error("METIS_PartGraphKway failed with status " + std::to_string(status));
    }
    for (PetscInt i = 0; i < nv; ++i) owner[i] = part[i];
  }
  GF_CALL(PetscFree(xadj));
  GF_CALL(PetscFree(adjncy));
  return owner;
}

std::vector<PetscInt> petscOwners(DM serial, const std::string& type) {
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(serial));
  PetscPartitioner part = nullptr;
  GF_CALL(PetscPartitionerCreate(comm, &part));
  PetscSection partSection = nullptr;
  IS partition = nullptr;
  try {
    GF_CALL(PetscPartitionerSetType(part, type.c_str()));
    GF_CALL(PetscSectionCreate(comm, &partSection));
    GF_CALL(PetscPartitionerDMPlexPartition(part, serial, nullptr, partSection, &partition));
    PetscInt cStart = 0, cEnd = 0;
    GF_CALL(DMPlexGetHeightStratum(serial, 0, &cStart, &cEnd));
    std::vector<PetscInt> owner(cEnd - cStart, 0);
    PetscInt pStart = 0, pEnd = 0;
    GF_CALL(PetscSectionGetChart(partSection, &pStart, &pEnd));
    const PetscInt* cells = nullptr;
    GF_CALL(ISGetIndices(partition, &cells));
    for (PetscInt q = pStart; q < pEnd; ++q) {
      PetscInt n = 0, off = 0;
      GF_CALL(PetscSectionGetDof(partSection, q, &n));
      GF_CALL(PetscSectionGetOffset(partSection, q, &off));
      for (PetscInt i = 0; i < n; ++i) owner[cells[off + i] - cStart] = q;
    }
    GF_CALL(ISRestoreIndices(partition, &cells));
    ISDestroy(&partition);
    PetscSectionDestroy(&partSection);
    PetscPartitionerDestroy(&part);
    return owner;
  } catch (...) {
    ISDestroy(&partition);
    PetscSectionDestroy(&partSection);
    PetscPartitionerDestroy(&part);
    throw;
  }
}

}  // namespace

std::vector<PetscInt> partitionCells(DM serial, const std::string& type) {
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(serial));
  int size = 1;
  MPI_Comm_size(comm, &size);
  if (type == "metis") return metisOwners(serial, size);
  return petscOwners(serial, type);
}

PetscInt countCutFaces(DM serial, const std::vector<PetscInt>& owner) {
  PetscInt fStart = 0, fEnd = 0, cStart = 0, cEnd = 0;
  GF_CALL(DMPlexGetHeightStratum(serial, 1, &fStart, &fEnd));
  GF_CALL(DMPlexGetHeightStratum(serial, 0, &cStart, &cEnd));
  if (cEnd - cStart != static_cast<PetscInt>(owner.size())) return 0;
  PetscInt cut = 0;
  for (PetscInt f = fStart; f < fEnd; ++f) {
    PetscInt n = 0;
    const PetscInt* support = nullptr;
    GF_CALL(DMPlexGetSupportSize(serial, f, &n));
    if (n != 2) continue;
    GF_CALL(DMPlexGetSupport(serial, f, &support));
    if (owner[support[0] - cStart] != owner[support[1] - cStart]) ++cut;
  }
  return cut;
}

DM distributeMesh(DM serial, const std::string& type) {
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(serial));
  int size = 1, rank = 0;
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  if (size == 1) return nullptr;
  PetscPartitioner part = nullptr;
  GF_CALL(DMPlexGetPartitioner(serial, &part));
  if (type == "metis") {
    const std::vector<PetscInt> owner = metisOwners(serial, size);
    GF_CALL(PetscPartitionerSetType(part, PETSCPARTITIONERSHELL));
    if (rank == 0) {
      std::vector<PetscInt> sizes(size, 0), points(owner.size()), start(size, 0);
      for (PetscInt o : owner) ++sizes[o];
      for (int q = 1; q < size; ++q) start[q] = start[q - 1] + sizes[q - 1];
      for (std::size_t c = 0; c < owner.size(); ++c) points[start[owner[c]]++] = static_cast<PetscInt>(c);
      GF_CALL(PetscPartitionerShellSetPartition(part, size, sizes.data(), points.data()));
    } else {
      GF_CALL(PetscPartitionerShellSetPartition(part, size, nullptr, nullptr));
    }
  } else {
    GF_CALL(PetscPartitionerSetType(part, type.c_str()));
  }
  DM distributed = nullptr;
  GF_CALL(DMPlexDistribute(serial, 0, nullptr, &distributed));
  return distributed;
}

}  // namespace gradfric::fem

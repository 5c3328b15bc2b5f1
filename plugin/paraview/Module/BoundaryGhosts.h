// SPDX-License-Identifier: BSD-3-Clause
// One layer of ghost faces across partition boundaries, for filters whose
// result at a vertex depends on all faces around it (vertex normals).
//
// VTK 9.2's vtkGhostCellsGenerator produced no ghost faces for the
// vtkPolyData pieces that RedistributeDataSet + Extract Surface hand us
// (tried inline and as an upstream proxy), so this is done directly: every
// rank sends the faces touching its partition boundary (edges used by one
// local face) to every other rank (MPI all-gather of coordinates), and each
// rank appends the received faces that share a vertex with its own
// boundary, matched by exact coordinates, after its own polygons (their new
// points after its own points, their attributes zero). DropBorrowedFaces
// removes them again after the filter ran (vtkRemoveGhosts zeroed the
// point data of polydata in VTK 9.2). Collective: every rank must call it.
#pragma once

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataSetAttributes.h>
#include <vtkIdList.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkDataArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkFieldData.h>

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace shadinglab::paraview
{

using Coordinates = std::array<double, 3>;

/// Cell array flagging the borrowed faces (1) in WithNeighbourFaces' output.
constexpr const char* kBorrowedArray = "ShadingLabBorrowed";

namespace detail
{

/// The points on the local partition boundary (edges used by exactly one
/// local face): flags per point, and their ids by coordinates.
inline void BoundaryPoints(
  vtkPolyData* input, std::vector<char>& onBoundary, std::map<Coordinates, vtkIdType>& boundaryIds)
{
  vtkCellArray* polys = input->GetPolys();
  std::map<std::pair<vtkIdType, vtkIdType>, int> edgeUse;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    polys->GetCellAtId(c, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = ids->GetId(k), b = ids->GetId((k + 1) % n);
      ++edgeUse[{ std::min(a, b), std::max(a, b) }];
    }
  }
  onBoundary.assign(static_cast<size_t>(input->GetNumberOfPoints()), 0);
  for (const auto& [edge, uses] : edgeUse)
  {
    if (uses == 1)
    {
      onBoundary[edge.first] = onBoundary[edge.second] = 1;
    }
  }
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    if (onBoundary[i])
    {
      Coordinates p;
      input->GetPoint(i, p.data());
      boundaryIds.emplace(p, i);
    }
  }
}

/// The faces within `rings` rings of the boundary, as [n, x0, y0, z0, ...].
inline std::vector<double> FacesNearBoundary(
  vtkPolyData* input, const std::vector<char>& onBoundary, int rings)
{
  vtkCellArray* polys = input->GetPolys();
  vtkNew<vtkIdList> ids;
  std::vector<char> near(onBoundary);
  std::vector<char> sendFace(static_cast<size_t>(polys->GetNumberOfCells()), 0);
  for (int ring = 0; ring < rings; ++ring)
  {
    std::vector<char> next(near);
    for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
    {
      polys->GetCellAtId(c, ids);
      bool touches = false;
      for (vtkIdType k = 0; k < ids->GetNumberOfIds() && !touches; ++k)
      {
        touches = near[ids->GetId(k)] != 0;
      }
      if (touches)
      {
        sendFace[c] = 1;
        for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
        {
          next[ids->GetId(k)] = 1;
        }
      }
    }
    near.swap(next);
  }
  std::vector<double> send;
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    if (!sendFace[c])
    {
      continue;
    }
    polys->GetCellAtId(c, ids);
    send.push_back(static_cast<double>(ids->GetNumberOfIds()));
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      double p[3];
      input->GetPoint(ids->GetId(k), p);
      send.insert(send.end(), p, p + 3);
    }
  }
  return send;
}

/// Every rank's `send` to every rank (MPI all-gather): the other ranks'
/// faces, each as its corners' coordinates. Collective.
inline std::vector<std::vector<Coordinates>> ExchangeFaces(
  vtkMultiProcessController* controller, const std::vector<double>& send)
{
  const int ranks = controller->GetNumberOfProcesses();
  const int me = controller->GetLocalProcessId();
  vtkIdType length = static_cast<vtkIdType>(send.size());
  std::vector<vtkIdType> lengths(static_cast<size_t>(ranks)), offsets(static_cast<size_t>(ranks));
  controller->AllGather(&length, lengths.data(), 1);
  vtkIdType total = 0;
  for (int r = 0; r < ranks; ++r)
  {
    offsets[r] = total;
    total += lengths[r];
  }
  std::vector<double> received(static_cast<size_t>(std::max<vtkIdType>(total, 1)));
  controller->AllGatherV(send.data(), received.data(), length, lengths.data(), offsets.data());
  std::vector<std::vector<Coordinates>> faces;
  for (int r = 0; r < ranks; ++r)
  {
    for (vtkIdType at = offsets[r]; at < offsets[r] + lengths[r];)
    {
      const auto n = static_cast<vtkIdType>(received[at++]);
      std::vector<Coordinates> corners(static_cast<size_t>(n));
      for (vtkIdType k = 0; k < n; ++k, at += 3)
      {
        corners[k] = { received[at], received[at + 1], received[at + 2] };
      }
      if (r != me)
      {
        faces.push_back(std::move(corners));
      }
    }
  }
  return faces;
}

/// Which of the received faces lie within `rings` rings of this rank's
/// boundary: ring 1 touches its boundary points, ring k a point of ring
/// k-1. Indices into `candidates`, ring by ring.
inline std::vector<size_t> FacesWithinRings(const std::vector<std::vector<Coordinates>>& candidates,
  const std::map<Coordinates, vtkIdType>& boundaryIds, int rings)
{
  std::map<Coordinates, char> reached;
  for (const auto& entry : boundaryIds)
  {
    reached.emplace(entry.first, 1);
  }
  std::vector<char> taken(candidates.size(), 0);
  std::vector<size_t> chosen;
  for (int ring = 0; ring < rings; ++ring)
  {
    std::vector<size_t> fresh;
    for (size_t f = 0; f < candidates.size(); ++f)
    {
      if (taken[f])
      {
        continue;
      }
      for (const Coordinates& p : candidates[f])
      {
        if (reached.count(p))
        {
          taken[f] = 1;
          fresh.push_back(f);
          break;
        }
      }
    }
    for (size_t f : fresh)
    {
      for (const Coordinates& p : candidates[f])
      {
        reached.emplace(p, 1);
      }
      chosen.push_back(f);
    }
  }
  return chosen;
}

/// Grows every array of `data` from `from` to `to` tuples, the new ones
/// zero (tuple by tuple: vtkFieldData::SetNumberOfTuples lost the existing
/// values here).
inline void GrowWithZeros(vtkFieldData* data, vtkIdType from, vtkIdType to)
{
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = data->GetAbstractArray(a);
    auto* numeric = vtkDataArray::SafeDownCast(array);
    if (!numeric)
    {
      array->Resize(to);
      array->SetNumberOfTuples(to);
      continue;
    }
    const std::vector<double> zeros(static_cast<size_t>(numeric->GetNumberOfComponents()), 0.0);
    for (vtkIdType i = from; i < to; ++i)
    {
      numeric->InsertTuple(i, zeros.data());
    }
  }
}

} // namespace detail

/// A copy of `input` with the neighbouring ranks' faces within `rings`
/// rings of its partition boundary appended (flagged in kBorrowedArray);
/// `added` is their count. One ring gives every boundary vertex all of its
/// faces (normals); two rings make subdivision's limit stencils, whose
/// reach shrinks by half each level (1 + 1/2 + ... < 2 base rings), see
/// only true neighbours.
inline vtkSmartPointer<vtkPolyData> WithNeighbourFaces(
  vtkPolyData* input, vtkMultiProcessController* controller, vtkIdType& added, int rings = 1)
{
  // Every rank takes part in the exchange below, even with nothing to send.
  added = 0;
  std::vector<char> onBoundary;
  std::map<Coordinates, vtkIdType> boundaryIds;
  detail::BoundaryPoints(input, onBoundary, boundaryIds);
  const std::vector<std::vector<Coordinates>> candidates =
    detail::ExchangeFaces(controller, detail::FacesNearBoundary(input, onBoundary, rings));

  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->DeepCopy(input);
  vtkPoints* points = output->GetPoints();
  vtkCellArray* outPolys = output->GetPolys();
  const vtkIdType localPoints = output->GetNumberOfPoints();
  const vtkIdType localCells = output->GetNumberOfCells();
  std::map<Coordinates, vtkIdType> newIds; // ghost points, shared by ghost faces
  std::vector<vtkIdType> face;
  for (size_t f : detail::FacesWithinRings(candidates, boundaryIds, rings))
  {
    face.clear();
    for (const Coordinates& p : candidates[f])
    {
      auto local = boundaryIds.find(p);
      if (local != boundaryIds.end())
      {
        face.push_back(local->second);
        continue;
      }
      auto ghost = newIds.find(p);
      if (ghost == newIds.end())
      {
        ghost = newIds.emplace(p, points->InsertNextPoint(p.data())).first;
      }
      face.push_back(ghost->second);
    }
    outPolys->InsertNextCell(static_cast<vtkIdType>(face.size()), face.data());
    ++added;
  }
  // Attributes of the new points and faces: zero.
  detail::GrowWithZeros(output->GetPointData(), localPoints, output->GetNumberOfPoints());
  vtkCellData* cd = output->GetCellData();
  detail::GrowWithZeros(cd, localCells, output->GetNumberOfCells());
  vtkNew<vtkUnsignedCharArray> borrowed;
  borrowed->SetName(kBorrowedArray);
  borrowed->SetNumberOfTuples(output->GetNumberOfCells());
  borrowed->Fill(0);
  for (vtkIdType c = localCells; c < output->GetNumberOfCells(); ++c)
  {
    borrowed->SetValue(c, 1);
  }
  cd->AddArray(borrowed);
  return output;
}

/**
 * Removes the polygons flagged in kBorrowedArray (the faces
 * WithNeighbourFaces appended, or the faces a filter made from them) and
 * the points no remaining cell uses, keeping the order of everything else,
 * and drops the flag array.
 */
inline void DropBorrowedFaces(vtkPolyData* mesh, vtkPolyData* output)
{
  auto* flags = vtkUnsignedCharArray::SafeDownCast(mesh->GetCellData()->GetArray(kBorrowedArray));
  vtkCellArray* polys = mesh->GetPolys();
  const vtkIdType firstPoly = mesh->GetNumberOfVerts() + mesh->GetNumberOfLines();
  auto isBorrowed = [&](vtkIdType poly) {
    return flags && flags->GetValue(firstPoly + poly) != 0;
  };
  std::vector<vtkIdType> newId(static_cast<size_t>(mesh->GetNumberOfPoints()), -1);
  vtkNew<vtkIdList> ids;
  auto markCells = [&](vtkCellArray* cells, bool polygons) {
    for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
    {
      if (polygons && isBorrowed(c))
      {
        continue;
      }
      cells->GetCellAtId(c, ids);
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        newId[ids->GetId(k)] = 0;
      }
    }
  };
  markCells(mesh->GetVerts(), false);
  markCells(mesh->GetLines(), false);
  markCells(polys, true);
  vtkIdType kept = 0;
  for (auto& id : newId)
  {
    id = id == 0 ? kept++ : -1;
  }
  vtkNew<vtkPoints> points;
  points->SetDataType(mesh->GetPoints()->GetDataType());
  points->SetNumberOfPoints(kept);
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyAllocate(mesh->GetPointData(), kept);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    if (newId[i] >= 0)
    {
      points->SetPoint(newId[i], mesh->GetPoint(i));
      outPD->CopyData(mesh->GetPointData(), i, newId[i]);
    }
  }
  output->SetPoints(points);
  std::vector<vtkIdType> keptCells; // input cell ids, in output order
  auto remap = [&](vtkCellArray* cells, vtkIdType cellBase, bool polygons) {
    vtkNew<vtkCellArray> out;
    for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
    {
      if (polygons && isBorrowed(c))
      {
        continue;
      }
      cells->GetCellAtId(c, ids);
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        ids->SetId(k, newId[ids->GetId(k)]);
      }
      out->InsertNextCell(ids);
      keptCells.push_back(cellBase + c);
    }
    return out;
  };
  output->SetVerts(remap(mesh->GetVerts(), 0, false));
  output->SetLines(remap(mesh->GetLines(), mesh->GetNumberOfVerts(), false));
  output->SetPolys(remap(polys, firstPoly, true));
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(mesh->GetCellData(), static_cast<vtkIdType>(keptCells.size()));
  for (size_t c = 0; c < keptCells.size(); ++c)
  {
    outCD->CopyData(mesh->GetCellData(), keptCells[c], static_cast<vtkIdType>(c));
  }
  outCD->RemoveArray(kBorrowedArray);
  output->GetFieldData()->ShallowCopy(mesh->GetFieldData());
}

} // namespace shadinglab::paraview

// A sparse matrix of id lists, one list per voxel: the identifiers matrix I
// and the TBV matrix T of Batagelo & Wu (section 3), 2D, or 3D as the 2D matrix
// of height * depth rows (voxel (x, y, z) in row y + z * height, as BitMatrix). Only voxels that hold ids
// use list storage: each voxel keeps a 4-byte head index into one pool of
// (id, next) nodes shared by the whole matrix, and removed nodes go to a free
// list, so after the first frames adding and removing ids allocates nothing.
// The head array itself is allocated on the first add(), so a matrix that is
// never written (T in a scene without dynamic objects) costs no memory.
//
// Coordinates are voxel indices of a width x height grid (callers check bounds;
// asserts guard them). Ids are any int32. Lists are unordered (newest first) and
// may hold the same id twice if it is added twice; callers add each id once.
//
// Cost: add O(1); remove O(list length); clear() O(voxels touched since the last
// clear) when built with track_touched, else O(voxels).
#pragma once
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gridcull {

class IdListMatrix {
public:
    // Sizes the matrix and empties it, freeing all storage (the head array comes
    // back on the next add()); to the shape it has already, it only empties it
    // and keeps its storage, so that a culler reset on the same scene reuses
    // what it grew (release() frees it). `track_touched` keeps a list of voxels
    // written since the last clear() so that clear() costs only those; use it for
    // matrices cleared every frame, not for ones that mostly add and remove.
    void resize(int width, int height, bool track_touched, int depth = 1, bool linked = false);
    // Frees all storage.
    void release();

    int width() const { return width_; }
    int height() const { return height_; }
    int depth() const { return rows_ / (height_ > 0 ? height_ : 1); }
    // The row that holds voxels (*, y, z).
    int row(int y, int z) const {
        assert(y >= 0 && y < height_ && z >= 0 && y + z * height_ < rows_);
        return y + z * height_;
    }

    void add(int x, int y, int32_t id);
    // Handles: with `linked` set in resize(), add() returns the node that holds
    // the id, and removeNode() takes it out in O(1) (a doubly linked list), for
    // matrices whose ids come and go often (T). Without `linked`, add() returns
    // the node too but only remove() may take it out.
    int32_t addNode(int x, int y, int32_t id);
    void removeNode(int32_t node);
    // Removes one occurrence of id from voxel (x, y); false when it is not there.
    bool remove(int x, int y, int32_t id);
    // Empties every list, keeping the capacity of the pool.
    void clear();

    bool empty(int x, int y) const {
        assert(x >= 0 && y >= 0 && x < width_ && y < rows_);
        return heads_.empty() || heads_[index(x, y)] < 0;
    }
    // Calls fn(id) for every id in voxel (x, y).
    template <typename Fn>
    void forEach(int x, int y, Fn&& fn) const {
        if (empty(x, y)) return;
        for (int32_t n = heads_[index(x, y)]; n >= 0; n = nodes_[size_t(n)].next)
            fn(nodes_[size_t(n)].id);
    }
    bool contains(int x, int y, int32_t id) const;
    int listLength(int x, int y) const;

    // Ids stored over all voxels, and voxels with a non-empty list. O(1).
    int64_t idCount() const { return live_nodes_; }
    int64_t nonEmptyVoxels() const { return non_empty_; }
    // Bytes held: head array, node pool and touched list (their capacities).
    size_t memoryBytes() const;

private:
    struct Node {
        int32_t id;
        int32_t next;
    };
    size_t index(int x, int y) const { return size_t(y) * size_t(width_) + size_t(x); }

    int width_ = 0;
    int height_ = 0;
    int rows_ = 0;  // height * depth
    bool track_touched_ = false;
    std::vector<int32_t> heads_;  // -1: empty; allocated on the first add()
    std::vector<Node> nodes_;
    int32_t free_head_ = -1;
    std::vector<int32_t> touched_;  // voxel indices, may repeat
    // With `linked`: per node, its predecessor, or -(voxel index + 1) for a head.
    bool linked_ = false;
    std::vector<int32_t> prev_;
    int64_t live_nodes_ = 0;
    int64_t non_empty_ = 0;
};

}  // namespace gridcull

#include "grid/id_list_matrix.h"

#include <algorithm>

namespace gridcull {

void IdListMatrix::resize(int width, int height, bool track_touched, int depth, bool linked) {
    assert(width >= 0 && height >= 0 && depth >= 1);
    if (width == width_ && height == height_ && height * depth == rows_ &&
        track_touched == track_touched_ && linked == linked_) {
        // The same shape: keep the storage a reset culler grew (see the header).
        clear();
        return;
    }
    linked_ = linked;
    std::vector<int32_t>().swap(prev_);
    assert(width >= 0 && height >= 0 && depth >= 1);
    width_ = width;
    height_ = height;
    rows_ = height * depth;
    track_touched_ = track_touched;
    std::vector<int32_t>().swap(heads_);  // re-allocated lazily by add()
    std::vector<Node>().swap(nodes_);
    std::vector<int32_t>().swap(touched_);
    free_head_ = -1;
    live_nodes_ = 0;
    non_empty_ = 0;
}

void IdListMatrix::release() {
    width_ = height_ = rows_ = 0;
    std::vector<int32_t>().swap(heads_);
    std::vector<Node>().swap(nodes_);
    std::vector<int32_t>().swap(touched_);
    std::vector<int32_t>().swap(prev_);
    free_head_ = -1;
    live_nodes_ = 0;
    non_empty_ = 0;
}

void IdListMatrix::add(int x, int y, int32_t id) { addNode(x, y, id); }

int32_t IdListMatrix::addNode(int x, int y, int32_t id) {
    assert(x >= 0 && y >= 0 && x < width_ && y < rows_);
    if (heads_.empty()) heads_.assign(size_t(width_) * size_t(rows_), -1);
    int32_t n;
    if (free_head_ >= 0) {
        n = free_head_;
        free_head_ = nodes_[size_t(n)].next;
    } else {
        n = int32_t(nodes_.size());
        nodes_.push_back(Node{0, -1});
        if (linked_) prev_.push_back(-1);
    }
    const size_t v = index(x, y);
    if (heads_[v] < 0) {
        ++non_empty_;
        if (track_touched_) touched_.push_back(int32_t(v));
    }
    nodes_[size_t(n)] = Node{id, heads_[v]};
    if (linked_) {
        prev_[size_t(n)] = -int32_t(v) - 1;
        if (heads_[v] >= 0) prev_[size_t(heads_[v])] = n;
    }
    heads_[v] = n;
    ++live_nodes_;
    return n;
}

void IdListMatrix::removeNode(int32_t n) {
    assert(linked_ && n >= 0 && size_t(n) < nodes_.size());
    Node& node = nodes_[size_t(n)];
    const int32_t before = prev_[size_t(n)];
    if (before < 0) {
        const size_t v = size_t(-before - 1);
        heads_[v] = node.next;
        if (node.next < 0) --non_empty_;
    } else {
        nodes_[size_t(before)].next = node.next;
    }
    if (node.next >= 0) prev_[size_t(node.next)] = before;
    node.next = free_head_;
    free_head_ = n;
    --live_nodes_;
}

bool IdListMatrix::remove(int x, int y, int32_t id) {
    if (empty(x, y)) return false;
    const size_t v = index(x, y);
    int32_t* link = &heads_[v];
    while (*link >= 0) {
        Node& node = nodes_[size_t(*link)];
        if (node.id == id) {
            const int32_t n = *link;
            if (linked_) {
                removeNode(n);
                return true;
            }
            *link = node.next;
            node.next = free_head_;
            free_head_ = n;
            --live_nodes_;
            if (heads_[v] < 0) --non_empty_;
            return true;
        }
        link = &node.next;
    }
    return false;
}

void IdListMatrix::clear() {
    if (heads_.empty()) return;
    if (track_touched_) {
        for (const int32_t v : touched_) heads_[size_t(v)] = -1;
    } else {
        std::fill(heads_.begin(), heads_.end(), -1);
    }
    touched_.clear();
    nodes_.clear();
    prev_.clear();
    free_head_ = -1;
    live_nodes_ = 0;
    non_empty_ = 0;
}

bool IdListMatrix::contains(int x, int y, int32_t id) const {
    bool found = false;
    forEach(x, y, [&](int32_t v) { found = found || v == id; });
    return found;
}

int IdListMatrix::listLength(int x, int y) const {
    int n = 0;
    forEach(x, y, [&](int32_t) { ++n; });
    return n;
}

size_t IdListMatrix::memoryBytes() const {
    return heads_.capacity() * sizeof(int32_t) + nodes_.capacity() * sizeof(Node) +
           touched_.capacity() * sizeof(int32_t) + prev_.capacity() * sizeof(int32_t);
}

}  // namespace gridcull

// SPDX-License-Identifier: MIT
#include "engine/core/ecs/sparse_set.hpp"

#include <algorithm>
#include <sstream>

#include "engine/core/error.hpp"

namespace engine::ecs {

std::uint32_t& SparseSet::sparseEntry(std::uint32_t index) {
    const std::size_t page = index >> kPageBits;
    if (page >= pages_.size()) pages_.resize(page + 1);
    if (!pages_[page]) {
        pages_[page] = std::make_unique<std::uint32_t[]>(kPageSize);
        std::fill_n(pages_[page].get(), kPageSize, kAbsent);
    }
    return pages_[page][index & kPageMask];
}

std::size_t SparseSet::insert(Entity e) {
    if (locked()) throwLocked("insert", e);
    std::uint32_t& entry = sparseEntry(e.index());  // may allocate: before any change
    const std::size_t position = dense_.size();
    dense_.push_back(e);
    entry = static_cast<std::uint32_t>(position);
    return position;
}

bool SparseSet::erase(Entity e) {
    const std::size_t position = find(e);
    if (position == npos) return false;
    if (locked()) throwLocked("erase", e);
    eraseComponentAt(position);
    const Entity last = dense_.back();
    dense_[position] = last;
    pages_[last.index() >> kPageBits][last.index() & kPageMask] = static_cast<std::uint32_t>(position);
    pages_[e.index() >> kPageBits][e.index() & kPageMask] = kAbsent;
    dense_.pop_back();
    return true;
}

void SparseSet::throwLocked(std::string_view action, Entity e) const {
    std::ostringstream msg;
    msg << "ecs: cannot " << action << ' ' << e << " in '" << name_
        << "' while a view over it is iterating; record the change in a CommandBuffer";
    throw Error(msg.str());
}

}  // namespace engine::ecs

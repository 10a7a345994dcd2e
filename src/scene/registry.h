#pragma once
/// \file
/// \brief A list of things RayCache offers by name: caches, orders, complete searches,
/// overlays. Each is registered once, with its name, one line that describes it and what
/// makes it; the command line's choices, the GUI's menus, the page's menus (through the
/// web edition's bindings), the benchmarks' tables and the web tests all read the list.
///
/// RayCache's own addition; the paper has no such list.
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rc {

/// The registered entries of one kind, in the order they were registered (the order of
/// menus and tables). `Entry` has at least `std::string name` and `std::string description`.
template <class Entry>
class Registry {
public:
    /// Adds `e`; returns its index (its number in menus and kinds).
    /// \throws std::logic_error when the name is empty or already taken.
    int add(Entry e) {
        if (e.name.empty()) throw std::logic_error("a registered entry needs a name");
        if (find(e.name)) throw std::logic_error("'" + e.name + "' is registered twice");
        entries_.push_back(std::move(e));
        return int(entries_.size()) - 1;
    }
    const std::vector<Entry>& entries() const { return entries_; }
    auto begin() const { return entries_.begin(); }
    auto end() const { return entries_.end(); }
    std::size_t size() const { return entries_.size(); }
    const Entry& operator[](std::size_t i) const { return entries_.at(i); }
    /// The entry named `name`, or null.
    const Entry* find(std::string_view name) const {
        for (const Entry& e : entries_)
            if (e.name == name) return &e;
        return nullptr;
    }
    /// The index of the entry named `name`, or -1.
    int indexOf(std::string_view name) const {
        for (std::size_t i = 0; i < entries_.size(); ++i)
            if (entries_[i].name == name) return int(i);
        return -1;
    }
    /// Every name, in order.
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const Entry& e : entries_) out.push_back(e.name);
        return out;
    }

private:
    std::vector<Entry> entries_;
};

}  // namespace rc

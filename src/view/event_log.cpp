#include "view/event_log.h"

#include <cstring>
#include <iterator>
#include <stdexcept>

namespace rc {

namespace {

// Unsigned numbers in 7-bit groups, low first, the high bit set on all but the last byte
void putVarint(std::uint8_t*& p, std::uint64_t v) {
    while (v >= 0x80) {
        *p++ = std::uint8_t(v | 0x80);
        v >>= 7;
    }
    *p++ = std::uint8_t(v);
}
std::uint64_t getVarint(const std::uint8_t*& p) {
    std::uint64_t v = 0;
    for (int shift = 0;; shift += 7) {
        const std::uint8_t b = *p++;
        v |= std::uint64_t(b & 0x7f) << shift;
        if (!(b & 0x80)) return v;
    }
}
// Signed numbers folded onto unsigned ones: 0, -1, 1, -2, ... as 0, 1, 2, 3, ...
void putSigned(std::uint8_t*& p, std::int64_t v) {
    putVarint(p, (std::uint64_t(v) << 1) ^ std::uint64_t(v >> 63));
}
std::int64_t getSigned(const std::uint8_t*& p) {
    const std::uint64_t u = getVarint(p);
    return std::int64_t(u >> 1) ^ -std::int64_t(u & 1);
}
template <class T>
void putRaw(std::uint8_t*& p, const T& v) {
    std::memcpy(p, &v, sizeof(T));
    p += sizeof(T);
}
template <class T>
void getRaw(const std::uint8_t*& p, T& v) {
    std::memcpy(&v, p, sizeof(T));
    p += sizeof(T);
}

// The header's two bytes: kind (2 bits), decision (2), reason (3), same origin (1);
// flags (3), no hit distance (1), region changed (1), step (2: same, one more, coded), raw (1)
enum : std::uint8_t { kSameOrigin = 0x80, kNoT = 0x08, kRegionChanged = 0x10, kRawHeader = 0x80 };
enum : std::uint8_t { kStepSame = 0, kStepNext = 1, kStepCoded = 2 };
// The first byte: which of the numbers after it are not there, being zero (or one): in a
// fill, neighbouring rays mostly follow the same path, hit and leave the same objects and
// look as far back for their pixel's previous ray. kHeaderSame: no header either, the
// event is of the kind, decision, reason, flags, origin, region and hit distance (none or
// not) of the one before, one step after it
enum : std::uint8_t {
    kPixelSame = 0x01, kNodeSame = 0x02, kHitSame = 0x04, kOriginSame = 0x08, kNoTests = 0x10, kBackSame = 0x20,
    kHeaderSame = 0x40, kOneTest = 0x80
};
constexpr float kNone = -1.0f;
// How far back the previous event of event `index` is: 0 for none, 1 for one that is not
// before it (kept as it is), else index - previous + 1
std::int64_t backOf(std::int32_t previous, std::int64_t index) {
    if (previous == -1) return 0;
    return previous >= 0 && previous < index ? index - previous + 1 : 1;
}
const EventRecord kStart{};

}  // namespace

void EventLog::dropRays() {
    if (size_ != 0) throw std::logic_error("EventLog::dropRays: the log already holds events");
    dropRays_ = true;
}

void EventLog::push_back(const EventRecord& given) {
    // Without its ray, the event reads back as it is stored: o and d zero (so every event's
    // origin is the one before it, and costs nothing), and t none (its ray's answer, the
    // object it hit, gives it again)
    EventRecord r = given;
    if (dropRays_) {
        std::fill(std::begin(r.o), std::end(r.o), 0.0f);
        r.d[0] = r.d[1] = 0;
        r.t = kNone;
    }
    // [encode]
    // Against the event before it in its group: the first of a group against nothing
    const bool first = size_ % kGroup == 0;
    const EventRecord& b = first ? kStart : last_;
    const std::int64_t index = std::int64_t(size_);
    std::uint8_t buf[kMaxEvent];
    std::uint8_t* p = buf;
    const bool sameOrigin = std::memcmp(r.o, b.o, sizeof r.o) == 0;
    const bool noT = std::memcmp(&r.t, &kNone, sizeof r.t) == 0;
    const std::int64_t step = std::int64_t(r.step) - b.step;
    const std::uint8_t stepCode = step == 0 ? kStepSame : step == 1 ? kStepNext : kStepCoded;
    const bool headerSame = r.kind == b.kind && r.decision == b.decision && r.reason == b.reason &&
                            r.flags == b.flags && sameOrigin && noT == (std::memcmp(&b.t, &kNone, sizeof b.t) == 0) &&
                            r.region == b.region && stepCode == kStepNext;
    std::uint8_t& same = *p++;
    same = headerSame ? kHeaderSame : 0;
    const bool narrow = r.kind < 4 && r.decision < 4 && r.reason < 8 && r.flags < 8;
    if (!headerSame) {
        *p++ = narrow ? std::uint8_t(r.kind | r.decision << 2 | r.reason << 4 | (sameOrigin ? kSameOrigin : 0)) : 0;
        *p++ = std::uint8_t((narrow ? r.flags : 0) | (noT ? kNoT : 0) | (r.region != b.region ? kRegionChanged : 0) |
                            stepCode << 5 | (narrow ? 0 : kRawHeader));
    }
    if (!headerSame && !narrow) {
        for (std::uint8_t v : {r.kind, r.decision, r.reason, r.flags}) *p++ = v;
        *p++ = sameOrigin ? 1 : 0;
    }
    // A number against the one before, left out when the same (`bit`) or, with `nextBit`, one more
    const auto put = [&](std::int64_t delta, std::uint8_t bit, std::uint8_t nextBit = 0) {
        if (delta == 0) same |= bit;
        else if (delta == 1 && nextBit) same |= nextBit;
        else putSigned(p, delta);
    };
    if (stepCode == kStepCoded) putSigned(p, step);
    put(std::int64_t(r.pixel) - b.pixel, kPixelSame);
    put(std::int64_t(r.node) - b.node, kNodeSame);
    // Neighbouring rays mostly hit and leave the same objects: both against the one before
    put(std::int64_t(r.hit) - b.hit, kHitSame);
    put(std::int64_t(r.origin) - b.origin, kOriginSame);
    put(r.tests, kNoTests, kOneTest);
    if (r.region != b.region) putSigned(p, std::int64_t(r.region) - b.region);
    // The pixel's previous event, as how far back it is (0 none, 1 coded as it is), against
    // the same of the event before: a fill's neighbouring rays look about as far back
    const std::int64_t back = backOf(r.previous, index);
    put(back - (first ? 0 : backOf(b.previous, index - 1)), kBackSame);
    if (back == 1) putSigned(p, r.previous);
    if (!sameOrigin) putRaw(p, r.o);
    if (!dropRays_) putRaw(p, r.d);
    if (!noT) putRaw(p, r.t);
    // [encode]
    const std::size_t n = std::size_t(p - buf);
    if (chunks_.empty() || used_.back() + n > kChunk) {
        chunks_.emplace_back(new std::uint8_t[kChunk]);  // untouched until written
        used_.push_back(0);
    }
    if (first) groups_.push_back(std::uint64_t(chunks_.size() - 1) * kChunk + used_.back());
    std::memcpy(chunks_.back().get() + used_.back(), buf, n);
    used_.back() += std::uint32_t(n);
    ++size_;
    last_ = r;
}

std::uint64_t EventLog::decode(std::uint64_t pos, std::size_t index, const EventRecord& b, EventRecord& r) const {
    const std::uint8_t* const start = chunks_[pos / kChunk].get() + pos % kChunk;
    const std::uint8_t* p = start;
    const std::uint8_t same = *p++;
    // The header the event before would have had, one step on
    std::uint8_t h0 = kSameOrigin, h1 = std::uint8_t(kStepNext << 5);
    if (std::memcmp(&b.t, &kNone, sizeof b.t) == 0) h1 |= kNoT;
    bool sameOrigin = true;
    if (same & kHeaderSame) {
        r.kind = b.kind;
        r.decision = b.decision;
        r.reason = b.reason;
        r.flags = b.flags;
    } else {
        h0 = *p++;
        h1 = *p++;
        sameOrigin = h0 & kSameOrigin;
    }
    if (!(same & kHeaderSame) && (h1 & kRawHeader)) {
        r.kind = *p++;
        r.decision = *p++;
        r.reason = *p++;
        r.flags = *p++;
        sameOrigin = *p++ != 0;
    } else if (!(same & kHeaderSame)) {
        r.kind = h0 & 3;
        r.decision = (h0 >> 2) & 3;
        r.reason = (h0 >> 4) & 7;
        r.flags = h1 & 7;
    }
    const auto get = [&](std::uint8_t bit, std::uint8_t nextBit = 0) -> std::int64_t {
        return same & bit ? 0 : same & nextBit ? 1 : getSigned(p);
    };
    const std::uint8_t stepCode = (h1 >> 5) & 3;
    r.step = std::int32_t(b.step + (stepCode == kStepSame ? 0 : stepCode == kStepNext ? 1 : getSigned(p)));
    r.pixel = std::int32_t(b.pixel + get(kPixelSame));
    r.node = std::int32_t(b.node + get(kNodeSame));
    r.hit = std::int32_t(b.hit + get(kHitSame));
    r.origin = std::int32_t(b.origin + get(kOriginSame));
    r.tests = std::int32_t(get(kNoTests, kOneTest));
    r.region = h1 & kRegionChanged ? std::int32_t(b.region + getSigned(p)) : b.region;
    const bool first = index % kGroup == 0;
    const std::int64_t back = (first ? 0 : backOf(b.previous, std::int64_t(index) - 1)) + get(kBackSame);
    r.previous = back == 0 ? -1 : back == 1 ? std::int32_t(getSigned(p)) : std::int32_t(std::int64_t(index) - back + 1);
    if (sameOrigin) std::memcpy(r.o, b.o, sizeof r.o);
    else getRaw(p, r.o);
    if (dropRays_) r.d[0] = r.d[1] = 0;
    else getRaw(p, r.d);
    if (h1 & kNoT) r.t = kNone;
    else getRaw(p, r.t);
    return pos + std::uint64_t(p - start);
}

std::uint64_t EventLog::skipEnd(std::uint64_t pos) const {
    const std::size_t chunk = pos / kChunk;
    return chunk < used_.size() && pos % kChunk >= used_[chunk] ? std::uint64_t(chunk + 1) * kChunk : pos;
}

std::size_t EventLog::decodeGroup(std::size_t g, EventRecord* out) const {
    const std::size_t n = std::min(kGroup, size_ - g * kGroup);
    std::uint64_t pos = groups_[g];
    for (std::size_t k = 0; k < n; ++k) pos = decode(skipEnd(pos), g * kGroup + k, k == 0 ? kStart : out[k - 1], out[k]);
    return n;
}

EventRecord EventLog::operator[](std::size_t i) const { return *from(i); }

void EventLog::truncate(std::size_t n) {
    if (n >= size_) return;
    // Where event n starts, and the event before it (what the next one is coded against)
    std::uint64_t pos = groups_[n / kGroup];
    EventRecord before;
    for (std::size_t i = n / kGroup * kGroup; i < n; ++i) {
        EventRecord r;
        pos = skipEnd(decode(skipEnd(pos), i, before, r));
        before = r;
    }
    // The first event of a group is coded against nothing, so `before` is all that is needed
    last_ = before;
    const std::size_t chunk = pos / kChunk;
    if (n == 0) {
        chunks_.clear();
        used_.clear();
    } else if (chunk < chunks_.size()) {
        chunks_.resize(chunk + 1);
        used_.resize(chunk + 1);
        used_[chunk] = std::uint32_t(pos % kChunk);
    }
    groups_.truncate((n + kGroup - 1) / kGroup);
    size_ = n;
}

std::size_t EventLog::bytes() const {
    return chunks_.size() * kChunk + chunks_.capacity() * sizeof(chunks_[0]) + used_.capacity() * sizeof(used_[0]) +
           groups_.bytes();
}

EventLog::const_iterator::const_iterator(const EventLog* log, std::size_t i) : log_(log), i_(i) {
    if (i_ >= log_->size_) return;
    // From the start of its group
    const std::size_t first = i_ / kGroup * kGroup;
    pos_ = log_->groups_[i_ / kGroup];
    EventRecord before;
    for (std::size_t k = first; k <= i_; ++k) {
        pos_ = log_->decode(log_->skipEnd(pos_), k, before, current_);
        before = current_;
    }
}

EventLog::const_iterator& EventLog::const_iterator::operator++() {
    if (++i_ >= log_->size_) return *this;
    const EventRecord before = i_ % kGroup == 0 ? kStart : current_;
    pos_ = log_->decode(log_->skipEnd(pos_), i_, before, current_);
    return *this;
}

}  // namespace rc

// The per-thread scratch; its destructor sees the complete LeafScratch and BlobScratch.
#include "zeroset/accel/trace_scratch.hpp"

#include "zeroset/accel/blob.hpp"
#include "zeroset/accel/implicit_leaf.hpp"

namespace zeroset {

TraceScratch::TraceScratch(std::size_t leaf_count) : leaves_(leaf_count) {}

TraceScratch::~TraceScratch() = default;

TraceScratch::SpanLease::SpanLease(TraceScratch& scratch) : scratch_(scratch) {
    if (scratch.spans_in_use_ == scratch.span_pool_.size()) scratch.span_pool_.push_back(std::make_unique<SpanList>());
    list_ = scratch.span_pool_[scratch.spans_in_use_++].get();
    list_->clear();
}

}  // namespace zeroset

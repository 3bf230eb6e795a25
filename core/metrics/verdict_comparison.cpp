#include "metrics/verdict_comparison.hpp"

#include "math/invariant.hpp"

namespace shadowlab {
namespace {

bool judged(PixelVerdict v) { return v != PixelVerdict::none; }
bool right(PixelVerdict v) { return v == PixelVerdict::agree; }

PixelAgreement agreement(PixelVerdict a, PixelVerdict b) {
    if (right(a) && right(b)) return PixelAgreement::both_right;
    if (right(a)) return PixelAgreement::only_a_right;
    if (right(b)) return PixelAgreement::only_b_right;
    return PixelAgreement::both_wrong;
}

}  // namespace

VerdictComparison compare_verdicts(const ShadowError& a, const ShadowError& b) {
    assert_invariant(a.verdicts.size() == b.verdicts.size());  // one camera image
    VerdictComparison c;
    c.pixels.assign(a.verdicts.size(), PixelAgreement::none);
    size_t judged_in_one_only = 0;  // none under one reference
    for (size_t i = 0; i < a.verdicts.size(); ++i) {
        judged_in_one_only += judged(a.verdicts[i]) != judged(b.verdicts[i]);
        if (!judged(a.verdicts[i]) || !judged(b.verdicts[i])) continue;
        const PixelAgreement p = agreement(a.verdicts[i], b.verdicts[i]);
        c.pixels[i] = p;
        ++c.receiver_pixels;
        c.both_right += p == PixelAgreement::both_right;
        c.both_wrong += p == PixelAgreement::both_wrong;
        c.only_a_right += p == PixelAgreement::only_a_right;
        c.only_b_right += p == PixelAgreement::only_b_right;
    }
    assert_invariant(judged_in_one_only == 0);
    assert_invariant(c.receiver_pixels == a.receiver_pixels && c.receiver_pixels == b.receiver_pixels);
    return c;
}

}  // namespace shadowlab

// Hard shadows (lookup/hard_filter.cpp): its one tap at the centre, which no radius moves.
float shadowFilter_hard(int i, ShadowMapReceiver m, float rotation) { return shadowLitShare(i, m, 0.0, 0.0); }

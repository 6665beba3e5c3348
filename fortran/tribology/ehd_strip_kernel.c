/* The EHD strip table's interpolation at many nodes (issue #30): the inner loop of
 * adore_tribology_ehd_strip_table's strip_log_shear_nodes, which the fast EHD traction
 * (adore_tribology_ehd_traction) calls once a contact for its ~40 nodes.
 *
 * It computes exactly what strip_log_shear computes at each node, operation for
 * operation (the same roundings in the same order, so the same bits: checked by
 * test_ehd_strip_kernel in fortran/tests/test_traction_fast.f90 over 2e6 points and by
 * the full runs' prints), with the Lagrange weights of A and L as one SSE2 pair and the
 * table's rows as pairs.  gfortran computes strip_log_shear's weights one axis at a time
 * (its vectoriser leaves the pairs scalar), 110 instructions a node against ~60 here.
 * Without SSE2 the same arithmetic in plain C.  The constants (A0, L0, INV_H, the domain)
 * come from the Fortran module, so that both use the same doubles.
 *
 * For j = 0 .. n-1 with a[j] <= a_max and l[j] <= l_max:
 *     g[j] = G(a[j], max(l[j], l_min)),
 * degree-3 Lagrange interpolation on the 4 x 4 table nodes around the point: t = (x - x0)
 * INV_H, i = int(t) - 1, weights of x0 = t - i (in [1, 2)) at the nodes 0..3,
 * w0 = -x1 x2 x3 / 6, w1 = x0 x2 x3 / 2, w2 = -x0 x1 x3 / 2, w3 = x0 x1 x2 / 6 (xk = x0 - k),
 * the columns of A combined first (rows in pairs), then along L.  table: column-major
 * (nl rows of L, one column per A node).  Other nodes keep g[j] (the caller handles them);
 * a NaN argument gives g[j] = NaN.  Returns the number of nodes left to the caller. */
#include <stddef.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

int adore_strip_log_shear_nodes(int n, const double *restrict a, const double *restrict l, double *restrict g,
                                 const double *restrict table, int nl, double a0, double l0, double inv_h,
                                 double a_max, double l_min, double l_max)
{
    const double c0 = -1.0 / 6.0, c1 = 1.0 / 2.0, c2 = -1.0 / 2.0, c3 = 1.0 / 6.0;
#if defined(__SSE2__)
    const __m128d origin = _mm_set_pd(l0, a0), scale = _mm_set1_pd(inv_h);
    const __m128d one = _mm_set1_pd(1.0), two = _mm_set1_pd(2.0), three = _mm_set1_pd(3.0);
    const __m128d k0 = _mm_set1_pd(c0), k1 = _mm_set1_pd(c1), k2 = _mm_set1_pd(c2), k3 = _mm_set1_pd(c3);
    const __m128i ione = _mm_set1_epi32(1);
#endif
    int left = 0;
    for (int j = 0; j < n; j++) {
        double aj = a[j], lj = l[j];
        if (aj != aj || lj != lj) {
            /* NaN first, by quiet comparisons (an ordered one would raise `invalid`, which the
               checks build traps) */
            g[j] = aj + lj;
            continue;
        }
        if (!(aj <= a_max && lj <= l_max)) {
            left++;
            continue;
        }
        if (lj < l_min)
            lj = l_min;
#if defined(__SSE2__)
        /* element 0: along A, element 1: along L */
        __m128d t = _mm_mul_pd(_mm_sub_pd(_mm_set_pd(lj, aj), origin), scale);
        __m128i i = _mm_sub_epi32(_mm_cvttpd_epi32(t), ione);
        __m128d x0 = _mm_sub_pd(t, _mm_cvtepi32_pd(i));
        __m128d x1 = _mm_sub_pd(x0, one), x2 = _mm_sub_pd(x0, two), x3 = _mm_sub_pd(x0, three);
        __m128d p2 = _mm_mul_pd(x0, x1);
        __m128d p3 = _mm_mul_pd(p2, x2);
        __m128d s1 = _mm_mul_pd(x3, x2);
        __m128d s0 = _mm_mul_pd(s1, x1);
        __m128d w0 = _mm_mul_pd(k0, s0);
        __m128d w1 = _mm_mul_pd(_mm_mul_pd(k1, x0), s1);
        __m128d w2 = _mm_mul_pd(_mm_mul_pd(k2, p2), x3);
        __m128d w3 = _mm_mul_pd(k3, p3);
        int ia = _mm_cvtsi128_si32(i), il = _mm_cvtsi128_si32(_mm_shuffle_epi32(i, 1));
        const double *p = table + (ptrdiff_t)ia * nl + il;
        /* v(r) = ((wa0 T(r, 0) + wa1 T(r, 1)) + wa2 T(r, 2)) + wa3 T(r, 3), rows r in pairs */
        __m128d a0w = _mm_unpacklo_pd(w0, w0), a1w = _mm_unpacklo_pd(w1, w1);
        __m128d a2w = _mm_unpacklo_pd(w2, w2), a3w = _mm_unpacklo_pd(w3, w3);
        const double *q0 = p, *q1 = p + nl, *q2 = p + 2 * (ptrdiff_t)nl, *q3 = p + 3 * (ptrdiff_t)nl;
        __m128d v01 = _mm_add_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(a0w, _mm_loadu_pd(q0)), _mm_mul_pd(a1w, _mm_loadu_pd(q1))),
                                            _mm_mul_pd(a2w, _mm_loadu_pd(q2))),
                                 _mm_mul_pd(a3w, _mm_loadu_pd(q3)));
        __m128d v23 = _mm_add_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(a0w, _mm_loadu_pd(q0 + 2)),
                                                       _mm_mul_pd(a1w, _mm_loadu_pd(q1 + 2))),
                                            _mm_mul_pd(a2w, _mm_loadu_pd(q2 + 2))),
                                 _mm_mul_pd(a3w, _mm_loadu_pd(q3 + 2)));
        /* g = ((wl0 v0 + wl1 v1) + wl2 v2) + wl3 v3 */
        __m128d m01 = _mm_mul_pd(_mm_unpackhi_pd(w0, w1), v01);
        __m128d m23 = _mm_mul_pd(_mm_unpackhi_pd(w2, w3), v23);
        __m128d s = _mm_add_sd(m01, _mm_unpackhi_pd(m01, m01));
        s = _mm_add_sd(s, m23);
        s = _mm_add_sd(s, _mm_unpackhi_pd(m23, m23));
        _mm_store_sd(g + j, s);
#else
        double t[2] = {(aj - a0) * inv_h, (lj - l0) * inv_h}, w[4][2];
        int i[2];
        for (int d = 0; d < 2; d++) {
            i[d] = (int)t[d] - 1;
            double x0 = t[d] - (double)i[d];
            double x1 = x0 - 1.0, x2 = x0 - 2.0, x3 = x0 - 3.0;
            double p2 = x0 * x1, p3 = p2 * x2, s1 = x3 * x2, s0 = s1 * x1;
            w[0][d] = c0 * s0;
            w[1][d] = c1 * x0 * s1;
            w[2][d] = c2 * p2 * x3;
            w[3][d] = c3 * p3;
        }
        const double *p = table + (ptrdiff_t)i[0] * nl + i[1];
        double v[4];
        for (int r = 0; r < 4; r++)
            v[r] = w[0][0] * p[r] + w[1][0] * p[nl + r] + w[2][0] * p[2 * (ptrdiff_t)nl + r] +
                   w[3][0] * p[3 * (ptrdiff_t)nl + r];
        g[j] = w[0][1] * v[0] + w[1][1] * v[1] + w[2][1] * v[2] + w[3][1] * v[3];
#endif
    }
    return left;
}

/* SPDX-License-Identifier: BSD-3-Clause */
/* sort.c - heap sort and heap sift over small fixed arrays (the
 * MTT_MAX_MEAS cap's heap, ALGORITHMS.md §16; gated pairs, merge
 * candidates, joint events), and the shift that turns CSR cursors back
 * into starts (gating §4, clusters §9).
 *
 * Heap sort because it is O(n log n) in the worst case, needs no recursion
 * and no scratch memory (docs/DESIGN.md: bounded cost, no recursion).  It is not
 * stable, so every comparator breaks ties on an index: the order is total
 * and the result deterministic. */
#include "mtt_internal.h"

static void swap_bytes(unsigned char *a, unsigned char *b, size_t size)
{
    size_t k;
    for (k = 0; k < size; ++k) {
        unsigned char t = a[k];
        a[k] = b[k];
        b[k] = t;
    }
}

void mtt_heap_sift(void *base, size_t n, size_t size, size_t i, mtt_less_fn less, const void *ctx)
{
    unsigned char *a = (unsigned char *)base;
    /* Each pass moves one level down: at most log2(n) passes. */
    for (;;) {
        size_t l = 2u * i + 1u, r = l + 1u, top = i;
        if (l < n && less(a + top * size, a + l * size, ctx)) {
            top = l;
        }
        if (r < n && less(a + top * size, a + r * size, ctx)) {
            top = r;
        }
        if (top == i) {
            return;
        }
        swap_bytes(a + i * size, a + top * size, size);
        i = top;
    }
}

void mtt_sort(void *base, size_t n, size_t size, mtt_less_fn less, const void *ctx)
{
    unsigned char *a = (unsigned char *)base;
    size_t i;
    if (n < 2u) {
        return;
    }
    for (i = n / 2u; i > 0u; --i) {
        mtt_heap_sift(base, n, size, i - 1u, less, ctx);
    }
    for (i = n - 1u; i > 0u; --i) {
        swap_bytes(a, a + i * size, size);
        mtt_heap_sift(base, i, size, 0u, less, ctx);
    }
}

void mtt_csr_unshift(uint16_t *first, uint16_t n)
{
    uint16_t i, prev = 0;
    for (i = 0; i <= n; ++i) {
        const uint16_t end = first[i];
        first[i] = prev;
        prev = end;
    }
}

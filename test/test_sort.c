/* SPDX-License-Identifier: BSD-3-Clause */
/* test_sort.c - heap sort and heap sift (sort.c) against a simple
 * reference (insertion sort) on pseudo-random arrays from a fixed LCG,
 * with many duplicates. */
#include <string.h>

#include "mtt_internal.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static uint32_t lcg_state;

static uint32_t lcg(void)
{
    lcg_state = lcg_state * 1664525u + 1013904223u; /* Numerical Recipes LCG */
    return lcg_state >> 8;
}

static int less_int(const void *a, const void *b, const void *ctx)
{
    (void)ctx;
    return *(const int32_t *)a < *(const int32_t *)b;
}

static int greater_int(const void *a, const void *b, const void *ctx)
{
    (void)ctx;
    return *(const int32_t *)a > *(const int32_t *)b;
}

static void insertion_sort(int32_t *v, size_t n)
{
    size_t i, j;
    for (i = 1; i < n; ++i) {
        int32_t x = v[i];
        for (j = i; j > 0 && v[j - 1u] > x; --j) {
            v[j] = v[j - 1u];
        }
        v[j] = x;
    }
}

#define NMAX 600

static void test_ints_against_reference(void)
{
    static int32_t a[NMAX], ref[NMAX];
    int round;
    lcg_state = 12345u;
    for (round = 0; round < 400; ++round) {
        size_t n = (size_t)(lcg() % NMAX), i;
        /* value range from tiny (many duplicates) to wide */
        uint32_t range = (round % 4 == 0) ? 3u : (round % 4 == 1) ? 17u : (round % 4 == 2) ? 1000u : 1000000u;
        for (i = 0; i < n; ++i) {
            a[i] = (int32_t)(lcg() % range) - (int32_t)(range / 2u);
        }
        memcpy(ref, a, n * sizeof a[0]);
        insertion_sort(ref, n);
        mtt_sort(a, n, sizeof a[0], less_int, NULL);
        TEST_ASSERT_EQUAL_MEMORY(ref, a, n * sizeof a[0]);
    }
}

static void test_edge_sizes_and_patterns(void)
{
    int32_t a[64], ref[64];
    size_t n, i;
    for (n = 0; n <= 64; ++n) {
        /* ascending, descending, constant, organ pipe */
        int pat;
        for (pat = 0; pat < 4; ++pat) {
            for (i = 0; i < n; ++i) {
                a[i] = pat == 0 ? (int32_t)i
                     : pat == 1 ? (int32_t)(n - i)
                     : pat == 2 ? 7
                                : (int32_t)(i < n / 2u ? i : n - i);
            }
            memcpy(ref, a, n * sizeof a[0]);
            insertion_sort(ref, n);
            mtt_sort(a, n, sizeof a[0], less_int, NULL);
            if (n > 0) {
                TEST_ASSERT_EQUAL_MEMORY(ref, a, n * sizeof a[0]);
            }
        }
    }
}

static void test_descending_comparator(void)
{
    int32_t a[200];
    size_t i;
    lcg_state = 777u;
    for (i = 0; i < 200; ++i) {
        a[i] = (int32_t)(lcg() % 50u);
    }
    mtt_sort(a, 200, sizeof a[0], greater_int, NULL);
    for (i = 1; i < 200; ++i) {
        TEST_ASSERT_TRUE(a[i - 1u] >= a[i]);
    }
}

/* Records with a key and an index: a comparator that breaks ties on the
 * index gives a total order, so the result equals a stable sort. */
struct rec {
    float key;
    uint16_t idx;
    char pad[6];
};

static int less_rec(const void *a, const void *b, const void *ctx)
{
    const struct rec *p = (const struct rec *)a, *q = (const struct rec *)b;
    (void)ctx;
    if (p->key != q->key) {
        return p->key < q->key;
    }
    return p->idx < q->idx;
}

static void test_records_with_tie_break(void)
{
    static struct rec a[300];
    int round;
    lcg_state = 99u;
    for (round = 0; round < 50; ++round) {
        size_t n = 1u + (size_t)(lcg() % 300u), i;
        for (i = 0; i < n; ++i) {
            memset(&a[i], 0, sizeof a[i]);
            a[i].key = (float)(lcg() % 10u);
            a[i].idx = (uint16_t)i;
        }
        mtt_sort(a, n, sizeof a[0], less_rec, NULL);
        for (i = 1; i < n; ++i) {
            TEST_ASSERT_TRUE(a[i - 1u].key < a[i].key ||
                             (a[i - 1u].key == a[i].key && a[i - 1u].idx < a[i].idx));
        }
    }
}

/* The comparator gets the context pointer: sort indices by an external key. */
static int less_by_ctx(const void *a, const void *b, const void *ctx)
{
    const int32_t *key = (const int32_t *)ctx;
    uint16_t i = *(const uint16_t *)a, j = *(const uint16_t *)b;
    if (key[i] != key[j]) {
        return key[i] < key[j];
    }
    return i < j;
}

static void test_context_pointer(void)
{
    int32_t key[100];
    uint16_t ix[100];
    uint16_t i;
    lcg_state = 4242u;
    for (i = 0; i < 100; ++i) {
        key[i] = (int32_t)(lcg() % 20u);
        ix[i] = i;
    }
    mtt_sort(ix, 100, sizeof ix[0], less_by_ctx, key);
    for (i = 1; i < 100; ++i) {
        TEST_ASSERT_TRUE(key[ix[i - 1u]] < key[ix[i]] ||
                         (key[ix[i - 1u]] == key[ix[i]] && ix[i - 1u] < ix[i]));
    }
}

static void test_heap_sift_restores_max_heap(void)
{
    int32_t a[128];
    int round;
    lcg_state = 2024u;
    for (round = 0; round < 100; ++round) {
        size_t n = 2u + (size_t)(lcg() % 126u), i, k;
        for (i = 0; i < n; ++i) {
            a[i] = (int32_t)(lcg() % 40u);
        }
        /* heapify with sift, then replace the root and sift it down */
        for (i = n / 2u; i > 0u; --i) {
            mtt_heap_sift(a, n, sizeof a[0], i - 1u, less_int, NULL);
        }
        a[0] = (int32_t)(lcg() % 40u);
        mtt_heap_sift(a, n, sizeof a[0], 0u, less_int, NULL);
        for (k = 1; k < n; ++k) {
            TEST_ASSERT_TRUE(a[(k - 1u) / 2u] >= a[k]);
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_ints_against_reference);
    RUN_TEST(test_edge_sizes_and_patterns);
    RUN_TEST(test_descending_comparator);
    RUN_TEST(test_records_with_tie_break);
    RUN_TEST(test_context_pointer);
    RUN_TEST(test_heap_sift_restores_max_heap);
    return UNITY_END();
}

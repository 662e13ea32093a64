/*
 * How many heap allocations one shcontact_solve makes once the contact is set up (doc/api.md,
 * "No allocation on the call path"). This program replaces malloc, calloc and realloc by
 * counting wrappers around glibc's own (__libc_malloc, ...), so it builds on glibc only; the
 * test suite skips the check where it does not build.
 *
 * It prints, per solve after the warm-up calls:
 *   same_position N   at the same wheel position with new loads and creepages (expected 0)
 *   moved_position N  moving the wheel among positions already visited, t_y = 0, 1, 2, 4.733 mm,
 *                     with both load modes (expected 0: the workspaces only grow, and the
 *                     warm-up grew them to these positions' size)
 *   new_position N    at a new wheel position each time (0 once no larger table is needed;
 *                     otherwise the few reallocations that grow a workspace)
 */
#include <stddef.h>
#include <stdio.h>

#include "shcontact.h"

extern void *__libc_malloc(size_t size);
extern void *__libc_calloc(size_t count, size_t size);
extern void *__libc_realloc(void *pointer, size_t size);

static long allocations;

void *malloc(size_t size)
{
    __atomic_add_fetch(&allocations, 1, __ATOMIC_RELAXED);
    return __libc_malloc(size);
}

void *calloc(size_t count, size_t size)
{
    __atomic_add_fetch(&allocations, 1, __ATOMIC_RELAXED);
    return __libc_calloc(count, size);
}

void *realloc(void *pointer, size_t size)
{
    __atomic_add_fetch(&allocations, 1, __ATOMIC_RELAXED);
    return __libc_realloc(pointer, size);
}

/* Positions visited by the warm-up and then again, and the load mode of call i among them. */
static const double positions[] = {0.0, 1.0, 2.0, 4.733};
#define N_POSITIONS ((int)(sizeof positions / sizeof positions[0]))

static int moving_call(shcontact_contact *contact, int i, double *v)
{
    int mode = (i / N_POSITIONS) % 2 ? SHCONTACT_LOAD_NORMAL_FORCE : SHCONTACT_LOAD_VERTICAL_FORCE;
    return shcontact_solve(contact, positions[i % N_POSITIONS], 0.0, mode, 60.0e3 + 500.0 * i,
                           0.1e-3 * (i % 7 + 1), 0.061e-3, 2.74e-4, v);
}

int main(void)
{
    const int calls = 24;
    double v[SHCONTACT_RESULT_SIZE];
    shcontact_contact *contact = NULL;
    long before, same, moved, fresh;
    int i, status = 0;

    if (shcontact_create(&contact, "builtin:S1002", "builtin:UIC60", SHCONTACT_RIGHT) != 0)
        return 1;
    /* The first calls size the workspaces: one per load mode. */
    status |= shcontact_solve(contact, 4.733, 0.0, SHCONTACT_LOAD_VERTICAL_FORCE, 64.7e3, 0.58e-3,
                              0.061e-3, 2.74e-4, v);
    status |= shcontact_solve(contact, 4.733, 0.0, SHCONTACT_LOAD_NORMAL_FORCE, 64.7e3, 0.58e-3,
                              0.061e-3, 2.74e-4, v);

    before = allocations;
    for (i = 0; i < calls; i++) {
        int mode = i % 2 ? SHCONTACT_LOAD_NORMAL_FORCE : SHCONTACT_LOAD_VERTICAL_FORCE;
        status |= shcontact_solve(contact, 4.733, 0.0, mode, 60.0e3 + 500.0 * i,
                                  0.1e-3 * (i + 1), 0.061e-3, 2.74e-4, v);
    }
    same = allocations - before;

    /* Warm-up over the positions with both load modes, then the same moves again. */
    for (i = 0; i < 2 * N_POSITIONS; i++)
        status |= moving_call(contact, i, v);
    before = allocations;
    for (i = 0; i < calls; i++)
        status |= moving_call(contact, i, v);
    moved = allocations - before;

    before = allocations;
    for (i = 0; i < calls; i++)
        status |= shcontact_solve(contact, 4.0 + 0.03 * i, 0.0, SHCONTACT_LOAD_NORMAL_FORCE,
                                  64.7e3, 0.58e-3, 0.061e-3, 2.74e-4, v);
    fresh = allocations - before;

    shcontact_destroy(contact);
    printf("status %d\n", status);
    printf("same_position %.3f\n", (double)same / calls);
    printf("moved_position %.3f\n", (double)moved / calls);
    printf("new_position %.3f\n", (double)fresh / calls);
    return status != 0;
}

/* startup_m55.c - the start of the library's test images on qemu's
 * mps3-an547 (Cortex-M55, tests/ports/helium.mk): tests/cortexm/startup.c's
 * (vector table, FPU and MVE enabled through CPACR CP10/CP11, .bss zeroed,
 * semihosting I/O), plus what a hosted test's main expects: argc/argv
 * (argv[1] = FACET_M55_ARG when the build defines it: the accuracy test's
 * reduced random sample count) and an environment with
 * FACET_TEST_QUICK=2, the tests' own switch to their reduced counts (2: a
 * full-system emulator, fewer still where a test says so). */
#include <stdint.h>
#include <stdlib.h>

extern uint32_t __bss_start__[], __bss_end__[], __stack_top[];
extern int main(int argc, char **argv);
extern void initialise_monitor_handles(void);
extern char **environ;
void reset_handler(void);
void fault_handler(void);

__attribute__((section(".vectors"), used)) static void (*const vectors[16])(void) = {
    (void (*)(void))(uintptr_t)__stack_top, reset_handler,
    fault_handler, fault_handler, fault_handler, fault_handler, fault_handler,
};

static char quick_[] = "FACET_TEST_QUICK=2";
static char *env_[] = { quick_, NULL };
static char name_[] = "m55";
#if defined(FACET_M55_ARG)
static char arg_[] = FACET_M55_ARG;
static char *argv_[] = { name_, arg_, NULL };
#else
static char *argv_[] = { name_, NULL };
#endif

void reset_handler(void)
{
    uint32_t *p;
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20; /* CPACR: CP10, CP11 full access */
    __asm__ volatile("dsb\n\tisb" ::: "memory");
    for (p = __bss_start__; p < __bss_end__; p++)
        *p = 0;
    initialise_monitor_handles();
    environ = env_;
    exit(main((int)(sizeof argv_ / sizeof argv_[0]) - 1, argv_));
}

/* a fault ends the run as a failure instead of hanging qemu */
void fault_handler(void)
{
    exit(3);
}

void _init(void);
void _fini(void);
void _init(void) {}
void _fini(void) {}

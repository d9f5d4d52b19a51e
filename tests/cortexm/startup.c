/* startup.c - the smallest Cortex-M start for the fx tests under
 * qemu-system-arm (mps2-an385 / mps2-an386): a vector table with the stack
 * top and the reset handler, .bss zeroed (qemu loads .data in place from
 * the ELF), newlib's semihosting I/O opened, main run, its status returned
 * through semihosting exit.  Built with --specs=rdimon.specs -nostartfiles. */
#include <stdint.h>
#include <stdlib.h>

extern uint32_t __bss_start__[], __bss_end__[], __stack_top[];
extern int main(void);
extern void initialise_monitor_handles(void);
void reset_handler(void);
void fault_handler(void);

__attribute__((section(".vectors"), used)) static void (*const vectors[16])(void) = {
    (void (*)(void))(uintptr_t)__stack_top, reset_handler,
    fault_handler, fault_handler, fault_handler, fault_handler, fault_handler,
};

void reset_handler(void)
{
    uint32_t *p;
#if defined(__ARM_FP) && __ARM_FP
    /* a hard-float build: CP10 and CP11 full access (CPACR), before any FPU
     * instruction; the reset value faults on them */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    for (p = __bss_start__; p < __bss_end__; p++)
        *p = 0;
    initialise_monitor_handles();
    exit(main());
}

/* a fault ends the run as a failure instead of hanging qemu */
void fault_handler(void)
{
    exit(3);
}

/* -nostartfiles drops crti/crtn; newlib's exit still calls these */
void _init(void);
void _fini(void);
void _init(void) {}
void _fini(void) {}

/* derive_host.c — the runtime and Ctrl-C for the Python loader: derive.runtime.cbuild compiles
 * this file beside the model's translation unit in every library whose sources hold the runtime,
 * and the model's unit with DERIVE_RUNTIME_LINKED (the runtime compiled once, here, and linked).
 * The SIGINT handling is the loader's own, not part of the runtime an export carries.
 *
 * derive_sigint_guard(1) installs a SIGINT handler that sets a flag and makes that flag the
 * runtime's interrupt check (derive_set_interrupt_check); derive_sigint_guard(0) restores the
 * previous handler, clears the flag and returns 1 if an interrupt came. derive_sigint_request()
 * sets the flag from any thread (a caller that stops a run it did not start). The check stays
 * installed; with the flag clear it answers 0.
 */
#include <signal.h>

#include "derive_runtime.c"

int derive_sigint_guard(int on);
void derive_sigint_request(void);

static volatile sig_atomic_t derive_sigint_flag = 0;
static void (*derive_sigint_previous)(int) = SIG_DFL;
static int derive_sigint_installed = 0;

static void derive_sigint_handler(int sig)
{
    (void)sig;
    derive_sigint_flag = 1;
}

static int derive_sigint_check(void *data)
{
    (void)data;
    return derive_sigint_flag != 0;
}

int derive_sigint_guard(int on)
{
    int was = derive_sigint_flag;
    derive_set_interrupt_check(derive_sigint_check, 0);
    if (on && !derive_sigint_installed) {
        derive_sigint_flag = 0;
        derive_sigint_previous = signal(SIGINT, derive_sigint_handler);
        derive_sigint_installed = derive_sigint_previous != SIG_ERR;
    } else if (!on && derive_sigint_installed) {
        signal(SIGINT, derive_sigint_previous);
        derive_sigint_installed = 0;
    }
    if (!on)
        derive_sigint_flag = 0;
    return was;
}

void derive_sigint_request(void)
{
    derive_set_interrupt_check(derive_sigint_check, 0);
    derive_sigint_flag = 1;
}

/* A C program against the installed header and library (README "Use from C").
 * Checks the C interface against independent values: Tee's Table 1 as published (the
 * rho of rows 1-2 corrected, docs/ERRATA.md; 15 digits), the closed forms of radial
 * fall (46) and of the bound kappa (75), Saitoh's surface-to-surface tunnel (10), and
 * the statuses of bad input; four threads of its own call the library at once (the first
 * calls race to build the shared model). Prints "c_user: ok" and exits 0, or names the failed
 * checks and exits 1. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>
#include <quadmath.h>

#include <brachistochrone.h>

static const double pi = 3.14159265358979323846;
static int failures = 0, checks = 0;

static void check(int ok, const char *what)
{
    ++checks;
    if (!ok) {
        ++failures;
        printf("FAILED: %s\n", what);
    }
}

static int close_to(double value, double expected, double tolerance)
{
    return fabs(value - expected) <= tolerance * fmax(1.0, fabs(expected));
}

/* Radial fall from rest at r = 1 to rho (Tee eq. 46). */
static double radial_time(double rho)
{
    return (acos(2.0 * rho - 1.0) / 2.0 + sqrt(rho * (1.0 - rho))) / sqrt(2.0);
}

/* Tee (1998), Table 1 as published (15 significant digits). */
static const double rho[5] = {0.2, 0.5, 0.7, 0.9, 1.0};
static const double psi[5] = {1.2, 0.1, 1.8, 0.4, 2.0};
static const double r_bar[5] = {0.184781963328079, 0.252787093630160, 0.168913316595188,
                                0.838545794202334, 0.057854464393370};
static const double s[5] = {0.967544327890300, 0.505594850833648, 1.531621194881120,
                            0.442680075643429, 1.947547388961997};
static const double t[5] = {1.127755808164997, 0.914164272619962, 1.481218910277573,
                            1.058599268341289, 2.221060707125763};

/* One thread: every row of Table 1, from a different starting row; returns the number
   of rows that disagree with the published values. */
static void *solve_rows(void *first)
{
    long wrong = 0;
    int k;
    for (k = 0; k < 5; ++k) {
        int i = (int)(((long)first + k) % 5);
        double a, b, c;
        int code = brachistochrone_solve("inverse_square", 0.0, rho[i], psi[i], &a, &b, &c);
        if (code != 0 || !close_to(a, r_bar[i], 2e-15) || !close_to(b, s[i], 2e-15) ||
            !close_to(c, t[i], 2e-15) || brachistochrone_status_message(code)[0] != 's')
            ++wrong;
    }
    return (void *)wrong;
}

int main(void)
{
    double big_r[5], arc[5], time[5];
    int status[5];
    double a, b, c;
    int i, code;
    pthread_t threads[4];

    /* Four threads at once, before anything else built the model. */
    for (i = 0; i < 4; ++i)
        pthread_create(&threads[i], NULL, solve_rows, (void *)(long)i);
    for (i = 0; i < 4; ++i) {
        void *wrong;
        pthread_join(threads[i], &wrong);
        check(wrong == NULL, "4 threads solving Table 1 at once");
    }

    code = brachistochrone_solve_many("inverse_square", 0.0, 5, rho, psi, big_r, arc, time,
                                      status);
    check(code == 0, "solve_many: Table 1 solved");
    for (i = 0; i < 5; ++i) {
        check(status[i] == BRACHISTOCHRONE_OK, "Table 1 status");
        check(close_to(big_r[i], r_bar[i], 2e-15), "Table 1 R-bar");
        check(close_to(arc[i], s[i], 2e-15), "Table 1 s");
        check(close_to(time[i], t[i], 2e-15), "Table 1 t");
    }

    /* The power law with n = 2 is the inverse-square law (general engine). */
    code = brachistochrone_solve("power", 2.0, 0.9, 0.4, &a, &b, &c);
    check(code == 0 && close_to(a, r_bar[3], 2e-15) && close_to(c, t[3], 2e-15),
          "power n = 2 gives Table 1 row 4");

    /* Quad precision: row 4 again, and t to the published digits. */
    {
        __float128 qa, qb, qc;
        code = brachistochrone_solve_q("inverse_square", 0, 0.9Q, 0.4Q, &qa, &qb, &qc);
        check(code == 0 && fabsq(qc - 1.058599268341289Q) < 1e-15Q, "solve_q row 4");
    }

    /* Radial fall: psi = 0, R-bar does not exist; s = 1 - rho, t = (46). */
    code = brachistochrone_solve("inverse_square", 0.0, 0.3, 0.0, &a, &b, &c);
    check(code == 0 && isnan(a) && close_to(b, 0.7, 1e-15) &&
          close_to(c, radial_time(0.3), 1e-15), "radial fall (46)");

    /* Inaccessible (psi >= 2 pi/3): status 1, R and s NaN, t = kappa = 2 t(0) - t(rho). */
    code = brachistochrone_solve("inverse_square", 0.0, 0.5, 2.5, &a, &b, &c);
    check(code == 1 && isnan(a) && isnan(b) &&
          close_to(c, 2.0 * radial_time(0.0) - radial_time(0.5), 1e-15), "kappa (75)");

    /* Harmonic: surface to surface at angle pi/2, R_m = 1 - psi/pi = 1/2 and
       t = pi sqrt(1 - R_m^2) (Saitoh 10). */
    code = brachistochrone_solve("harmonic", 0.0, 1.0, pi / 2.0, &a, &b, &c);
    check(code == 0 && close_to(a, 0.5, 1e-15) && close_to(c, pi * sqrt(0.75), 1e-15),
          "harmonic tunnel (Saitoh 10)");

    /* Errors are statuses, with messages; NULL outputs are allowed. */
    code = brachistochrone_solve("gravity", 0.0, 0.5, 1.0, &a, NULL, NULL);
    check(code != 0 && isnan(a) && strlen(brachistochrone_status_message(code)) > 10,
          "unknown force: a status and a message");
    code = brachistochrone_solve("power", 0.5, 0.5, 1.0, NULL, NULL, NULL);
    check(code != 0 && code != 14, "power with exponent 0.5: its own status");
    code = brachistochrone_solve("inverse_square", 0.0, 1.5, 1.0, NULL, NULL, &c);
    check(code != 0 && isnan(c), "rho > 1 is an error");
    check(strcmp(brachistochrone_status_message(0), "solved") == 0, "message of status 0");
    check(brachistochrone_arithmetic_ok() == 1, "the x87 arithmetic at its defaults");
    check(strcmp(brachistochrone_status_message(-7), "unknown status") == 0,
          "message of a number that is no status");
    check(brachistochrone_solve_many("inverse_square", 0.0, -1, rho, psi, NULL, NULL, NULL,
                                     NULL) == -1, "n < 0");

    printf("%d checks, %d failed\n", checks, failures);
    if (failures != 0)
        return 1;
    printf("c_user: ok\n");
    return 0;
}

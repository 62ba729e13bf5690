#!/usr/bin/python3
"""Python side of bench/bench_stats.c: scikit-learn and scipy on the same data.

    OPENBLAS_NUM_THREADS=1 /usr/bin/python3 bench/bench_stats.py [--only fft|linkage|gmm|ks] DIR

DIR holds X.tsv (10,000 x 81) and labels.tsv written by build/bench/bench_stats.
EM starts from those labels through sklearn's own _initialize, as the C side
does. Each linkage runs in a fresh process so its peak RSS is its own, and its
merges are compared with the C side's (DIR/Z_<method>.tsv) when present:
rows whose ids or sizes differ, and the largest relative height difference.
"""
import os
import resource
import subprocess
import sys
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402


def load(d):
    X = np.loadtxt(os.path.join(d, "X.tsv"), skiprows=1)
    labels = np.loadtxt(os.path.join(d, "labels.tsv"), skiprows=1).astype(int)
    return X, labels


def bench_gmm(X, labels):
    try:
        from sklearn.mixture import GaussianMixture
    except ImportError:
        print("gmm_em   sklearn not importable by /usr/bin/python3: skipped")
        return

    class FromLabels(GaussianMixture):
        def _initialize_parameters(self, X, random_state):
            resp = np.zeros((X.shape[0], self.n_components))
            resp[np.arange(X.shape[0]), labels] = 1
            self._initialize(X, resp)

    g = FromLabels(n_components=30, covariance_type="full", tol=1e-3, reg_covar=1e-6, max_iter=100)
    # the thread's CPU time, as the C side (OpenBLAS at one thread)
    t0, w0 = time.thread_time(), time.perf_counter()
    g.fit(X)
    t, w = time.thread_time() - t0, time.perf_counter() - w0
    print(f"gmm_em   sklearn n={X.shape[0]} d={X.shape[1]} K=30 full: {t:.3f} s total thread CPU ({w:.3f} s wall), "
          f"{g.n_iter_} iterations, "
          f"{t / g.n_iter_:.4f} s/iteration, mean loglik {g.score(X):.10f}, converged {int(g.converged_)}")


def cpu_now():
    """User and system CPU seconds of this process so far."""
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime, r.ru_stime


def linkage_child(d, method, lib):
    """One linkage in a fresh process: wall and CPU time, peak RSS. lib is
    scipy or fastcluster (Muellner's library, from which scipy's linkage
    descends; Debian's python3-fastcluster, installed by scripts/noiselab setup)."""
    if lib == "fastcluster":
        try:
            import fastcluster
        except ImportError:
            print(f"linkage  fastcluster not importable by /usr/bin/python3 (apt-get install python3-fastcluster): skipped")
            return
        link = fastcluster.linkage_vector if method == "single" else fastcluster.linkage
    else:
        import scipy.cluster.hierarchy as sch
        link = sch.linkage
    X, _ = load(d)
    base = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    t0, (u0, s0) = time.perf_counter(), cpu_now()
    Z = link(X, method=method)
    t, (u1, s1) = time.perf_counter() - t0, cpu_now()
    u, s = u1 - u0, s1 - s0
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    tag = "scipy" if lib == "scipy" else "fastc"
    print(f"linkage  {tag} {method:8s} n={X.shape[0]} d={X.shape[1]}: {t:.3f} s, {u + s:.3f} s CPU = "
          f"{u:.3f} s user + {s:.3f} s system, top merge height {Z[-1, 2]:.10g}")
    print(f"linkage  {tag} {method:8s} peak RSS of the process {peak / 1024:.0f} MiB "
          f"({(peak - base) / 1024:.0f} MiB above the loaded data)")
    zc = os.path.join(d, f"Z_{method}.tsv")
    if os.path.exists(zc):   # the C side's merges (bench_stats.c), same data
        Zc = np.loadtxt(zc, skiprows=1)
        ids = int(np.sum(np.any(Zc[:, [0, 1, 3]] != Z[:, [0, 1, 3]], axis=1)))
        rel = float(np.max(np.abs(Zc[:, 2] - Z[:, 2]) / np.maximum(np.abs(Z[:, 2]), 1e-300)))
        same = int(np.sum(Zc[:, 2] == Z[:, 2]))
        print(f"linkage  {tag} {method:8s} against C: {ids} rows with other ids or sizes, heights equal in "
              f"{same} of {Z.shape[0]} rows, largest relative difference {rel:.3g}")


def bench_ks():
    import scipy.stats as st
    rng = np.random.default_rng(0)
    x = rng.uniform(0, 2 * np.pi, 512)
    cdf = st.uniform(0, 2 * np.pi).cdf
    reps = 3000
    # the thread's CPU time, as the C side: time descheduled on a loaded machine is not the call's
    t0 = time.thread_time()
    for i in range(reps):
        x[i % 512] = rng.uniform(0, 2 * np.pi)
        r = st.kstest(x, cdf)
    t = (time.thread_time() - t0) / reps
    print(f"ks       scipy n=512 kstest exact p: {t * 1e6:.1f} us/call thread CPU "
          f"(last D={r.statistic:.6f} p={r.pvalue:.6f})")


def bench_fft():
    """numpy's rfft2 and fft2 of a 512 x 512 real image: ms of CPU time per
    call, best of three rounds of >= 0.3 s (as the C side times nl_spectrum)."""
    x = np.random.default_rng(0).standard_normal((512, 512))
    for name, f in (("numpy rfft2 (half spectrum)", np.fft.rfft2), ("numpy fft2 (full spectrum)", np.fft.fft2)):
        best = (float("inf"), 0.0)
        for _ in range(3):
            n, c0, w0 = 0, time.thread_time(), time.perf_counter()
            while time.perf_counter() - w0 < 0.3:
                f(x)
                n += 1
            c, w = (time.thread_time() - c0) / n * 1e3, (time.perf_counter() - w0) / n * 1e3
            best = min(best, (c, w))
        print(f"fft2     py   512x512 {name:40s} {best[0]:7.3f} ms CPU/call ({best[1]:.3f} ms wall)")


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--linkage-child":
        d, method, lib = sys.argv[2].split(":")
        linkage_child(d, method, lib)
        return
    args = sys.argv[1:]
    only = None
    if len(args) >= 2 and args[0] == "--only":
        only, args = args[1], args[2:]
    if not args and only not in ("ks", "fft"):
        # the data files are bench_stats's, in the folder it names: no shared default
        print("usage: bench_stats.py [--only ks|fft|gmm|linkage] DIR (DIR: where build/bench/bench_stats "
              "wrote X.tsv and labels.tsv)", file=sys.stderr)
        sys.exit(2)
    d = args[0] if args else None
    if only in (None, "ks"):
        bench_ks()
    if only in (None, "fft"):
        bench_fft()
    if only not in (None, "gmm", "linkage"):
        return
    X, labels = load(d)
    if only in (None, "gmm"):
        bench_gmm(X, labels)
    if only == "gmm":
        return
    for method in ("complete", "average", "ward", "single"):
        for lib in ("scipy", "fastcluster"):
            sys.stdout.flush()
            subprocess.run([sys.executable, os.path.abspath(__file__), "--linkage-child", f"{d}:{method}:{lib}"],
                           check=True)


if __name__ == "__main__":
    main()

"""The time-against-error study from Python: shadinglab.accuracy's record
array, plotted with matplotlib when it is installed (pvpython or python3).

    pvpython examples/python/plot_study.py out/study.png

Each mode's frame time against its mean error over the shapes and levels of
the quick study (CPU renderer); lower left is better.
"""

import sys

import numpy

import shadinglab


def main(out):
    rows = shadinglab.accuracy(quick=True, backend="cpu")
    print(len(rows), "rows:", ", ".join(rows.dtype.names[:8]), "...")
    error, time = "mean_255", "frame_ms"
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        for mode in numpy.unique(rows.mode):
            chosen = rows[rows.mode == mode]
            print(f"{mode:12s} {numpy.median(chosen[time]):8.2f} ms  {numpy.median(chosen[error]):8.3f}")
        return
    figure, axes = plt.subplots(figsize=(7, 5), dpi=110)
    for mode in numpy.unique(rows.mode):
        chosen = rows[rows.mode == mode]
        axes.scatter(chosen[time], chosen[error], label=mode, s=18)
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("frame time (ms)")
    axes.set_ylabel("mean error against the exact surface (1/255)")
    axes.set_title("ShadingLab: time against error (quick study, CPU renderer)")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(title="mode")
    figure.tight_layout()
    figure.savefig(out)
    print("wrote", out)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "study.png")

"""What the Python examples share: where the scenes are, where figures go, --quick for CI."""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")  # files, no window: the examples run in CI and over ssh

EXAMPLES = pathlib.Path(__file__).resolve().parents[1]


def arguments(description):
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("--out-dir", type=pathlib.Path, default=pathlib.Path("python-figures"),
                    help="where the logs and figures go (default: ./python-figures)")
    ap.add_argument("--quick", action="store_true", help="a smaller, shorter run (what CI runs)")
    a = ap.parse_args()
    a.out_dir.mkdir(parents=True, exist_ok=True)
    return a

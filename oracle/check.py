#!/usr/bin/env python3
"""Independent checks of the oracle trajectories in oracle/ (see oracle/README.md).

Every reference file oracle/<path>.bin was written by FOSSSim from assets/<path>.xml. This script
does not run FOSSSim and shares no code with it: it reads the scene with xml.etree and the
trajectory with its own reader (fosssim_traj.py), and asserts, for each scene, physical or
closed-form properties that the numbers must have if the simulator is right: closed-form discrete
solutions, conservation laws, exact velocity exchanges, predicted collision times, and (for the
hybrid handler) that nothing overlaps at any step end.

usage: check.py [--root DIR] [-v | --markdown] [SCENE...]   (SCENE as a path relative to assets/, e.g. examples/drag.xml)
Exit code 0 when every check passed.
"""
import argparse
import os
import sys
import traceback


sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks_common import CHECKS, CheckFailed, expect  # noqa: E402
from checks_default_mode import generic  # noqa: E402
from fosssim_traj import Scene, Trajectory  # noqa: E402
import checks_examples  # noqa: E402,F401 - registers its checks
import checks_t2m2  # noqa: E402,F401 - registers its checks
import checks_t2m2_zones  # noqa: E402,F401 - registers its checks


# ---- driver ------------------------------------------------------------------------------------------

def read_mode(oracle):
    """The mode oracle/MODE says made the files: its last line that is not a comment."""
    path = os.path.join(oracle, 'MODE')
    if not os.path.exists(path):
        return None
    lines = [l.strip() for l in open(path) if l.strip() and not l.lstrip().startswith('#')]
    return lines[-1] if lines else ''


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--root', default=os.path.dirname(here), help='the repository (default: this file\'s parent)')
    ap.add_argument('--oracle', default=None, help='folder of the .bin files (default ROOT/oracle)')
    ap.add_argument('-v', '--verbose', action='store_true', help='print what each check established')
    ap.add_argument('--markdown', action='store_true', help='print one Markdown list item per scene (for oracle/README.md)')
    ap.add_argument('scenes', nargs='*')
    args = ap.parse_args()
    assets = os.path.join(args.root, 'assets')
    oracle = args.oracle or os.path.join(args.root, 'oracle')
    found = sorted(os.path.relpath(os.path.join(d, f), assets)
                   for d, _, files in os.walk(assets) for f in files
                   if f.endswith('.xml') and not os.path.relpath(d, assets).split(os.sep)[0] == 'showcase')
    scenes = args.scenes or found
    failed = 0
    # The checks of continuous-time and hybrid files (default_mode) are the default mode's promises:
    # files said to be made by another mode must not pass them unnoticed, nor files of no stated mode.
    mode = read_mode(oracle)
    mode_failed = mode != 'default'
    if mode_failed:
        print('FAIL %s: says %r; these checks are for files made in the default mode (no --compat)' %
              (os.path.join(oracle, 'MODE'), mode) if mode is not None else
              'FAIL %s is missing: the files must say which mode made them' % os.path.join(oracle, 'MODE'))
    elif args.verbose:
        print('mode: default (%s)' % os.path.join(oracle, 'MODE'))
    for rel in scenes:
        notes = []
        try:
            expect(rel in CHECKS, 'no check written for this scene')
            bin_path = os.path.join(oracle, os.path.splitext(rel)[0] + '.bin')
            expect(os.path.exists(bin_path), 'no oracle file %s' % bin_path)
            sc = Scene(os.path.join(assets, rel))
            tr = Trajectory(bin_path, sc)
            generic(sc, tr, notes)
            CHECKS[rel](sc, tr, notes)
            if args.markdown:
                print('- `%s`: %s.' % (os.path.splitext(rel)[0] + '.bin', '; '.join(notes)))
                continue
            print('ok   %s' % rel)
            if args.verbose:
                for n in notes:
                    print('       - ' + n)
        except Exception as e:  # noqa: BLE001 - report every scene
            failed += 1
            print('FAIL %s: %s' % (rel, e))
            if not isinstance(e, (CheckFailed, AssertionError)):
                traceback.print_exc()
    stale = sorted(set(CHECKS) - set(found))
    for rel in stale if not args.scenes else []:
        failed += 1
        print('FAIL %s: a check exists but the scene does not' % rel)
    if not args.markdown or failed or mode_failed:
        print('%d passed, %d failed%s' % (len(scenes) - min(failed, len(scenes)), failed,
                                          '; oracle/MODE failed' if mode_failed else ''))
    return 1 if failed or mode_failed else 0


if __name__ == '__main__':
    sys.exit(main())

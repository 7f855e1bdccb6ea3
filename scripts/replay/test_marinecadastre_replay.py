#!/usr/bin/env python3
"""Tests of the replay converter's reading of ownship's recorded track.

    python3 -m unittest discover -s scripts/replay -p 'test_*.py'
"""

import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import marinecadastre_replay as replay  # noqa: E402


def report(time_s, cog_deg, sog_kn):
    # (time, lat, lon, COG as MarineCadastre writes it, SOG): a course
    # above 204.8 is written as negative (course - 409.6).
    written = cog_deg - 409.6 if cog_deg >= 204.8 else cog_deg
    return (time_s, 40.7, -74.0, written, sog_kn)


class RecordedTurnRate(unittest.TestCase):
    def test_a_slow_turn_round_gives_its_rate(self):
        # JUSTINE's pattern (decision 52): nearly stopped on 230, round to
        # 317 in 66 s, then 023 in 84 s, then under way on 040.
        track = [
            report(0, 229.8, 1.3),
            report(66, 317.3, 1.0),
            report(150, 23.3, 7.1),
            report(213, 39.9, 9.0),
        ]
        self.assertAlmostEqual(replay.recorded_turn_rate_deg_s(track), 1.33)

    def test_no_faster_than_the_default_leaves_the_default(self):
        straight = [report(60 * i, 40.0 + (i % 2) * 2.0, 9.0) for i in range(10)]
        self.assertIsNone(replay.recorded_turn_rate_deg_s(straight))

    def test_reports_not_making_way_or_without_a_course_are_ignored(self):
        track = [
            report(0, 10.0, 0.2),  # at rest: its COG means nothing
            report(60, 190.0, 0.3),
            (120, 40.7, -74.0, -49.6, 5.0),  # COG not available (AIS 360)
            report(180, 100.0, 5.0),
        ]
        self.assertIsNone(replay.recorded_turn_rate_deg_s(track))


if __name__ == "__main__":
    unittest.main()

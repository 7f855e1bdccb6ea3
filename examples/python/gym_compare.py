"""Random actions against vorrt's planner in the Gymnasium environment
``vorrt.gym`` (nothing is trained): the same generated open-sea encounters,
each policy's mean return, goal rate and COLREGs findings.

    pip install './python[gym]'
    python examples/python/gym_compare.py --episodes 5 --targets 2
"""

import argparse
import sys
from statistics import mean
from typing import List

from gymnasium.utils.env_checker import check_env

import vorrt.gym as vgym


def main(argv: List[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--episodes", type=int, default=5)
    parser.add_argument("--targets", type=int, default=2)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args(argv)
    env = vgym.VorrtEnv(generator={"kind": "open-sea", "targets": args.targets})
    check_env(env.unwrapped, skip_render_check=True)
    env.action_space.seed(args.seed)
    policies = {
        "random": lambda observation: env.action_space.sample(),
        "vorrt planner": vgym.PlannerPolicy(env),
    }
    print(f"{'policy':<14} {'return':>8} {'goal':>6} {'clear':>6} {'findings':>9} {'steps':>6}")
    for name, policy in policies.items():
        runs = [vgym.episode(env, policy, args.seed + k) for k in range(args.episodes)]
        print(
            f"{name:<14} {mean(r['return'] for r in runs):8.1f}"
            f" {mean(r['reached_goal'] for r in runs):6.0%}"
            f" {mean(r['clearance_kept'] for r in runs):6.0%}"
            f" {mean(r['findings'] for r in runs):9.1f}"
            f" {mean(r['steps'] for r in runs):6.0f}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

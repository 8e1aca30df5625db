# `pm2dof report`: what the compiled model says (Me, cond(S^T S), rank of Y).
from ..options import model


def add_parser(sub, common):
    p = sub.add_parser("report", parents=[common], help="model report over the workspace",
                       description="Print the model's nominal parameters, Me at its own pose "
                       "(the middle of its first move, else the grid point farthest from both "
                       "singularities), the conditioning of S^T S and both singularity measures "
                       "(type I, type II) over the workspace, and the rank of the regressor Y "
                       "stacked over random states. Any model: points, platforms, revolute and "
                       "linear actuators, gravity.")
    return p


def run(args):
    from ...analysis.report import model_report
    print(model_report(model(args)))
    return 0

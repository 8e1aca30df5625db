# `pm2dof report`: what the compiled model says (Me, cond(S^T S), rank of Y).
from ..options import model


def add_parser(sub, common):
    p = sub.add_parser("report", parents=[common], help="model report over the workspace",
                       description="Print the nominal parameters, Me at the middle of the "
                       "paper's path, the conditioning of S^T S and min |sin(qb-qa)| over the "
                       "workspace, and the rank of the regressor Y stacked over random states.")
    return p


def run(args):
    from ...analysis.report import model_report
    print(model_report(model(args)))
    return 0

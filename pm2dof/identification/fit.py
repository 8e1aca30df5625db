# Identification from a log: filter, differentiate, stack the base regressor, weighted least squares.
"""``pm2dof identify fit``: least squares for the base parameters from a log.

The one pipeline of pm2dof's identification: a measured log (``fit LOG``) and a simulated
excitation run (``fit`` without a log, :func:`pm2dof.identification.excitation.simulated_log`)
go through it alike. Each step is a function below; :func:`identify_log` runs them all:

1. ``log_poses``: xe = fk(qa) per row, the passive angles from geometry (checks the log).
2. :func:`lowpass`: a zero-phase Butterworth low-pass (``scipy.signal.butter`` +
   ``sosfiltfilt``) on xe; the cutoff is :func:`choose_cutoff` (a multiple of the excitation
   band). Velocities and accelerations are central differences of the filtered positions.
3. At every sample the regressor rows Y(q, xed, xed, xedd)[:, base] and the task force
   S^T tau (eq. 13, tau averaged over the two hold intervals around t_k, which makes the
   zero-order hold's acceleration jump cancel exactly).
4. Parallel filtering and decimation: the *same* zero-phase low-pass on every regressor
   column and on the task force, then every r-th sample. Filtering is linear, so
   F(Y) theta = F(S^T tau) holds wherever Y theta = S^T tau holds: the equation stays exact
   while the controller's high-frequency torque (reacting to encoder noise) is removed from
   both sides.
5. Samples where an active joint is slower than ``min_joint_speed`` (and their neighbours
   within the filter's reach) are left out: there eq. 2's sign(qd) jumps and real friction
   (stiction, Stribeck) is not eq. 2. The threshold is in rad/s for a revolute actuator; a
   linear one's (PRR, RPR legs: qd in m/s) is ``min_joint_speed * SPEED_LEVER`` m/s
   (:func:`joint_speed_floor`).
6. Weighted least squares (:func:`weighted_ls`): OLS, then each task axis weighted by
   1/sigma of its residual; a Newey-West (Bartlett) covariance, since filtered residuals
   are correlated; ±2 sigma per base parameter; warnings for directions the data cannot
   determine.
7. The model error (:func:`model_error`): the pipeline is run again with each of its free
   choices changed (the cutoff halved, the joint-speed threshold doubled, every second sample
   dropped). With the right model these move the estimate by noise only; discretisation
   (the filter acting on a nonlinear regressor, finite differences) and friction outside
   eq. 2 (Stribeck) move it by their bias. The printed interval is ±(2 sigma + the sum of the
   three shifts): 2 sigma alone covers the noise, not these biases, and with the optimised
   excitation it missed the truth in up to 80 % of the Monte Carlo seeds.
"""
import math
from dataclasses import dataclass

import numpy as np

from ..core.errors import ArgumentError
from ..core.task import per_actuator
from .base import inertial_mask, parameter_units
from .log import LogError, log_poses

__all__ = ["lowpass", "choose_cutoff", "excitation_band", "differentiate", "stack_regressor", "weighted_ls",
           "weak_directions", "model_error", "identify_log", "Identification", "CUTOFF_FACTOR", "MIN_JOINT_SPEED",
           "MODEL_ERROR_CHOICES", "SPEED_LEVER", "joint_speed_floor", "speed_phrase"]

#: cutoff of the low-pass = CUTOFF_FACTOR x the highest excitation frequency. A 4th-order
#: Butterworth applied forward and backward passes f/fc = 0.1 with gain 1 - 1e-8: the
#: excitation is untouched, the tracking loop's content (tens of Hz) mostly kept, and the
#: encoder noise in the accelerations (growing like fc^2.5) stays small.
CUTOFF_FACTOR = 10.0
#: rad/s: samples where |qd_a,i| is below this for some joint are not used (eq. 2 jumps there)
MIN_JOINT_SPEED = 0.1
#: m/rad: a linear actuator's speed threshold is the revolute one times this lever (0.1 rad/s
#: -> 0.01 m/s): a revolute joint at 0.1 rad/s moves a point 0.1 m out at 0.01 m/s, and the
#: shipped linear actuators move at a few cm/s in an excitation
SPEED_LEVER = 0.1
FILTER_ORDER = 4


def lowpass(cutoff_hz, sample_period, order=FILTER_ORDER):
    """Second-order sections of a digital Butterworth low-pass (``scipy.signal.butter``).

    Applied with :func:`zero_phase` (forward and backward), its gain is |H(f)|^2: the
    magnitude squared of one pass, no phase shift.

    Parameters
    ----------
    cutoff_hz : float
        -3 dB frequency of one pass, Hz; below the Nyquist frequency 1 / (2 T).
    sample_period : float
        T, s.
    """
    from scipy import signal
    nyquist = 0.5 / sample_period
    if not (0 < cutoff_hz < nyquist):
        raise ArgumentError(f"filter cutoff {cutoff_hz:g} Hz must be in (0, {nyquist:g}) Hz "
                         f"(the Nyquist frequency of T = {sample_period:g} s)")
    return signal.butter(order, cutoff_hz, fs=1.0 / sample_period, output="sos")


def zero_phase(sos, x):
    """Apply ``sos`` forward and backward along axis 0 (``scipy.signal.sosfiltfilt``)."""
    from scipy import signal
    return signal.sosfiltfilt(sos, x, axis=0)


#: a spectral line belongs to the excitation if its power is within this of the largest line
#: (amplitude 1 %: a tracking loop's harmonics lie 55-70 dB down) ...
LINE_DB = 40.0
#: ... and this far above the noise floor (the median of the spectrum); see excitation_band
FLOOR_DB = 20.0


def _hann_leak(d):
    """Envelope of the Hann window's amplitude response d bins from a line (1 at d = 0):
    1 / (pi d |1 - d^2|) outside the main lobe (|d| >= 2), 1 inside it."""
    d = np.abs(d)
    return np.where(d >= 2, 1.0 / (np.pi * np.maximum(d, 2) * np.abs(1 - np.maximum(d, 2) ** 2)),
                    1.0)


def excitation_band(x, T):
    """The highest frequency, Hz, of a measured multi-sine or periodic motion ``x`` (N, d).

    The Hann-windowed power spectrum, summed over the axes. A plain FFT leaks a line's power
    far up the spectrum when the record is not a whole number of periods (the default
    multi-sine's 3.39 Hz read as 11-16 Hz from 99.99 % of the power). Its lines are the local
    maxima within :data:`LINE_DB` of the largest, :data:`FLOOR_DB` above the median (the noise
    floor) and 10 dB above the window's sidelobes of every stronger line (lines two bins apart,
    a periodic excitation of two periods, are told apart). The band is the highest line.
    """
    x = np.asarray(x, dtype=float)
    x = x - np.mean(x, axis=0)
    P = np.sum(np.abs(np.fft.rfft(x * np.hanning(len(x))[:, None], axis=0)) ** 2, axis=1)
    f = np.fft.rfftfreq(len(x), T)
    k = 1 + np.flatnonzero((P[1:-1] > P[:-2]) & (P[1:-1] >= P[2:]))
    if not k.size:
        return 0.0
    k = k[(P[k] >= P[k].max() * 10 ** (-LINE_DB / 10))
          & (P[k] >= np.median(P) * 10 ** (FLOOR_DB / 10))]
    lines = [j for j in k if all(P[j] >= 10 * P[i] * _hann_leak(j - i) ** 2
                                 for i in k if P[i] > P[j])]
    return float(f[max(lines)]) if lines else 0.0


def choose_cutoff(log, xe=None, factor=CUTOFF_FACTOR):
    """The low-pass cutoff for ``log``: ``factor`` x the highest excitation frequency.

    The band is the log's metadata ``excitation_max_hz`` (written by ``excite``); else it
    is estimated from the positions xe (N, 2) (:func:`excitation_band`: the highest line of
    their spectrum). Capped at 0.4 of the Nyquist frequency.

    Returns
    -------
    cutoff_hz, band_hz : float
    how : str
        Where the band came from (for the printed report).

    Raises
    ------
    LogError
        No excitation band: the positions do not move (names the log and ``--cutoff``).
    """
    T = log.period
    if "excitation_max_hz" in log.meta:
        band, how = float(log.meta["excitation_max_hz"]), "excitation_max_hz in the log"
    else:
        band = excitation_band(xe, T)
        how = "estimated: the highest line of the spectrum of fk(qa)"
    if not band > 0:
        raise LogError(f"{log.source}: the log shows no motion to identify from (no line in the "
                       f"spectrum of fk(qa)); the filter's cutoff cannot be chosen from it (give "
                       f"--cutoff HZ if the motion is there)")
    cap = 0.4 * 0.5 / T
    return min(factor * band, cap), band, how


def differentiate(x, T):
    """Central differences along axis 0: (v, a) at every sample; the two end samples copy
    their neighbours (they lie in the filter's discarded edge)."""
    v, a = np.empty_like(x), np.empty_like(x)
    v[1:-1] = (x[2:] - x[:-2]) / (2 * T)
    a[1:-1] = (x[2:] - 2 * x[1:-1] + x[:-2]) / (T * T)
    for z in (v, a):
        z[0], z[-1] = z[1], z[-2]
    return v, a


def joint_speed_floor(model, min_joint_speed):
    """(n,) the slow-sample threshold of each actuator in its own unit: ``min_joint_speed``
    rad/s for a revolute actuator, ``min_joint_speed * SPEED_LEVER`` m/s for a linear one
    (PRR, RPR legs)."""
    return np.array([min_joint_speed * (1.0 if leg.actuator == "revolute" else SPEED_LEVER)
                     for leg in model.spec.legs])


def speed_phrase(model, min_joint_speed):
    """The threshold in words for messages: "0.1 rad/s", "0.01 m/s", or both for mixed
    actuators."""
    rad, lin = f"{min_joint_speed:g} rad/s", f"{min_joint_speed * SPEED_LEVER:g} m/s"
    return per_actuator(model.spec.actuators, rad, lin, f"{rad} (revolute) or {lin}")


def stack_regressor(model, base, t, xe, tau, cutoff_hz, *, decimate=None,
                    min_joint_speed=MIN_JOINT_SPEED, order=FILTER_ORDER):
    """Steps 2-5 of the pipeline: the filtered, decimated base regressor and task force.

    Parameters
    ----------
    model : Model
    base : BaseParameters
        The base columns (:func:`pm2dof.identification.base.base_parameters`).
    t : ndarray (N,)
        Sample times, s (regular).
    xe : ndarray (N, m)
        Measured poses fk(qa), m (phi in rad; m = ``model.dof``).
    tau : ndarray (N, n)
        Torque applied over [t_k, t_k+1), N*m.
    cutoff_hz : float
    decimate : int, optional
        Keep every r-th sample (default: the largest r with 1 / (r T) >= 4 cutoff).
    min_joint_speed : float
        rad/s for a revolute actuator; a linear one's is this times :data:`SPEED_LEVER`, m/s
        (0: use every sample).

    Returns
    -------
    dict
        ``Phi`` (K, m, r) filtered base regressor rows, ``u`` (K, m) filtered S^T tau, N;
        ``t`` (K,) their times; ``xe``, ``xed``, ``xedd`` (N, m) the filtered motion;
        ``decimate``, ``edge`` (samples dropped at each end), ``n_slow`` (decimated samples
        left out as slow).
    """
    T = float(np.median(np.diff(t)))
    N, I = len(t), list(base.independent)
    sos = lowpass(cutoff_hz, T, order)
    xf = xe[0] + zero_phase(sos, xe - xe[0])   # about the first sample: a log at rest stays
    #                                            exactly at rest (xed = 0, sign(0) = 0: no fc)
    # C-contiguous rows (sosfiltfilt's result is not): the model's fast path takes them, a
    # strided row would be refused and copied on the checked path, ~5x slower per sample
    xf = np.ascontiguousarray(xf)
    v, a = differentiate(xf, T)
    tau_mid = np.empty_like(tau)
    tau_mid[0] = tau[0]
    tau_mid[1:] = 0.5 * (tau[1:] + tau[:-1])   # the hold intervals before and after t_k
    m = model.dof
    Y = np.empty((N, m, len(model.param_names)))
    S = np.empty((N, model.n_legs, m))
    q = np.empty(2 * model.n_legs)
    for k in range(N):                           # three calls into C per sample, no numpy
        model.ik(xf[k], out=q)
        model.S(q, out=S[k])
        model.Y(q, v[k], v[k], a[k], out=Y[k])   # eq. 13 with xrd = xed, xrdd = xedd
    Y = Y[:, :, I]
    u = np.matmul(S.transpose(0, 2, 1), tau_mid[:, :, None])[:, :, 0]     # S^T tau per sample
    slow = np.any(np.abs(np.matmul(S, v[:, :, None])[:, :, 0]) < joint_speed_floor(
        model, min_joint_speed), axis=1)
    Yf, uf = zero_phase(sos, Y), zero_phase(sos, u)   # parallel filtering: the same filter
    edge = int(math.ceil(3.0 / (cutoff_hz * T)))       # filtfilt's start-up transients
    r = decimate or max(1, int(1.0 / (4.0 * cutoff_hz * T)))
    reach = int(math.ceil(0.5 / (cutoff_hz * T)))      # a slow sample spoils this far
    if min_joint_speed > 0 and reach > 0:
        slow = np.convolve(slow.astype(float), np.ones(2 * reach + 1), mode="same") > 0
    ks = np.arange(edge, N - edge, r)
    keep = ks[~slow[ks]]
    return {"Phi": Yf[keep], "u": uf[keep], "t": np.asarray(t)[keep], "xe": xf, "xed": v,
            "xedd": a, "decimate": r, "edge": edge, "n_slow": int(len(ks) - len(keep)),
            "n_candidates": int(len(ks))}


def weighted_ls(Phi, u, lags=None):
    """Weighted least squares for Phi (K, m, r) theta_b = u (K, m), m task axes.

    Ordinary least squares first; then each task axis weighted by 1 / sigma of its OLS
    residual and solved again. Columns are scaled to unit norm for the solve (units differ).
    The covariance is Newey-West's (Bartlett weights, ``lags`` default floor(4 (K/100)^(2/9))):
    the residuals of filtered data are correlated, and the plain sigma^2 (A^T A)^-1 would be
    optimistic.

    Returns
    -------
    dict
        ``estimate`` (r,), ``std`` (r,) 1 sigma, ``cov`` (r, r), ``weights`` (m,) 1/N,
        ``residual`` (K, m) N (unweighted), ``A`` (mK, r) and ``b`` (mK,) the weighted system,
        ``rms`` (m,) N, ``r2`` (m,), ``lag1`` (lag-1 autocorrelation of the weighted
        residual), ``lags``, ``inflation`` (Newey-West over plain variance, geometric mean).
    """
    K, m, r = Phi.shape
    if m * K <= r:
        raise LogError(f"too short: {K} usable samples give {m * K} equations for {r} base "
                       f"parameters")

    def solve(w):
        A = (Phi * w[None, :, None]).reshape(-1, r)
        b = (u * w[None, :]).reshape(-1)
        scale = np.linalg.norm(A, axis=0)
        scale[scale == 0] = 1.0
        x, *_ = np.linalg.lstsq(A / scale, b, rcond=None)
        return A, b, x / scale

    _, _, x0 = solve(np.ones(m))
    res0 = u - Phi @ x0
    sig = np.sqrt(np.mean(res0 ** 2, axis=0))
    w = 1.0 / np.maximum(sig, 1e-300)
    A, b, x = solve(w)
    res = u - Phi @ x
    rw = res * w                                            # (K, m), ~unit variance
    Ak = Phi * w[None, :, None]
    g = np.einsum("kir,ki->kr", Ak, rw)                      # scores (K, r)
    L = int(math.floor(4 * (K / 100.0) ** (2.0 / 9.0))) if lags is None else int(lags)
    Sg = g.T @ g
    for lag in range(1, L + 1):
        G = g[lag:].T @ g[:-lag]
        Sg += (1.0 - lag / (L + 1.0)) * (G + G.T)
    scale = np.linalg.norm(A, axis=0)
    H = (A / scale).T @ (A / scale)
    Hi = np.linalg.inv(H) / np.outer(scale, scale)          # (A^T A)^-1
    dof = m * K - r
    cov = (m * K / dof) * Hi @ Sg @ Hi                        # sandwich, small-sample factor
    plain = (np.sum(rw ** 2) / dof) * Hi
    std = np.sqrt(np.diag(cov))
    tss = np.sum((u - u.mean(axis=0)) ** 2, axis=0)
    flat = rw.reshape(-1)
    lag1 = float(np.sum(rw[1:] * rw[:-1]) / np.sum(rw * rw)) if K > 1 else 0.0
    return {"estimate": x, "std": std, "cov": cov, "weights": w, "residual": res, "A": A,
            "b": b, "rms": np.sqrt(np.mean(res ** 2, axis=0)),
            "r2": 1.0 - np.sum(res ** 2, axis=0) / tss, "lag1": lag1, "lags": L,
            "inflation": float(np.exp(np.mean(np.log(np.diag(cov) / np.diag(plain))))),
            "n_equations": int(flat.size)}


def weak_directions(cov, estimate, names, rel=0.1, units=None):
    """Directions of the base parameters the data cannot determine.

    The covariance is made relative: each base parameter is divided by its size, |estimate|
    but at least 10 % of the largest |estimate| in the same unit (``units``: a PRR leg's alpha
    in kg against the platform's m_p, its gamma in kg m^2 against the other gammas and I_p),
    so a parameter near zero is judged against the scale of its unit, and a small one (a
    0.004 kg m^2 gamma) is not judged against a large one of another unit (a 1.3 kg alpha).
    An eigenvector of that relative covariance whose 2 sigma exceeds ``rel`` (default 10 %) is
    reported with its dominant parameters (coefficient above 0.2 of the largest); so is, on its
    own, any base parameter whose own 2 sigma exceeds ``rel`` of its size and that none of
    those directions names.

    Parameters
    ----------
    cov : ndarray (r, r)
        Covariance of the base parameters.
    estimate : ndarray (r,)
    names : list of str (r,)
        For the descriptions.
    rel : float
        The largest 2 sigma, relative to the size, that is not reported.
    units : list of str (r,), optional
        Each base parameter's unit (:func:`pm2dof.identification.base.parameter_units`);
        default: every inertial parameter in one group and every friction one in another
        (right only when they share a unit, as the paper's robot's inertias do).

    Returns
    -------
    list of (rel_2sigma, description), largest first
    """
    est = np.abs(np.asarray(estimate, dtype=float))
    if units is None:
        units = ["inertial" if i else "friction" for i in inertial_mask(names)]
    units = np.asarray(units, dtype=object)
    s = est.copy()
    for u in set(units):
        grp = units == u
        s[grp] = np.maximum(est[grp], 0.1 * est[grp].max())
    s = np.maximum(s, 1e-300)
    lam, V = np.linalg.eigh(cov / np.outer(s, s))
    out, named = [], set()
    for j in np.argsort(lam)[::-1]:
        r2s = 2 * math.sqrt(max(lam[j], 0.0))
        if r2s <= rel:
            break
        v = V[:, j] / np.abs(V[:, j]).max()
        terms = [(c, n) for c, n in sorted(zip(v, names), key=lambda z: -abs(z[0]))
                 if abs(c) > 0.2]
        named.update(n for _, n in terms)
        out.append((r2s, " ".join(f"{c:+.2f} {n}" for c, n in terms)))
    # a base parameter weak on its own but below 0.2 in every weak direction listed
    own = 2 * np.sqrt(np.maximum(np.diag(cov), 0.0)) / s
    out += [(float(own[k]), f"+1.00 {n}") for k, n in enumerate(names)
            if own[k] > rel and n not in named]
    return sorted(out, key=lambda z: -z[0])


#: the free choices :func:`model_error` changes, as printed
MODEL_ERROR_CHOICES = ("cutoff halved", "joint-speed threshold doubled", "sample rate halved")


def _half_rate(t, xe, tau):
    """Every second sample; the torque averaged over the two hold intervals it covers (the
    torque applied over [t_2j, t_2j+2))."""
    n = (len(t) - 1) // 2
    return t[0:2 * n:2], xe[0:2 * n:2], 0.5 * (tau[0:2 * n:2] + tau[1:2 * n:2])


def model_error(model, base, t, xe, tau, cutoff_hz, min_joint_speed, estimate):
    """Shifts of the base-parameter estimate when the pipeline's free choices change.

    Each of :data:`MODEL_ERROR_CHOICES` (cutoff / 2, ``min_joint_speed`` x 2, sample period
    x 2) is applied alone and the weighted least squares solved again. None of them should
    matter if eq. 2 with the filtered differences were exact: what they move is the bias
    of discretisation and of friction outside eq. 2, which the residuals' sigma misses.

    Returns
    -------
    ndarray (3, r)
        Estimate with the choice changed minus ``estimate``; a row of zeros where the changed
        pipeline has too few samples.
    """
    runs = [(t, xe, tau, 0.5 * cutoff_hz, min_joint_speed),
            (t, xe, tau, cutoff_hz, 2.0 * min_joint_speed),
            (*_half_rate(np.asarray(t), xe, np.asarray(tau)), cutoff_hz, min_joint_speed)]
    out = np.zeros((len(runs), base.r))
    for k, (tk, xk, uk, fc, v) in enumerate(runs):
        st = stack_regressor(model, base, tk, xk, uk, fc, min_joint_speed=v)
        if 2 * len(st["t"]) > 2 * base.r:
            out[k] = weighted_ls(st["Phi"], st["u"])["estimate"] - estimate
    return out


#: a logged torque this many times the model's tau_max is a units or limits mistake
TORQUE_SCALE_LIMIT = 2.0


def _check_torque_scale(model, log):
    """LogError if a logged torque exceeds tau_max by more than TORQUE_SCALE_LIMIT: the drives
    cannot apply it, so the log's units (mN m?) or the model file's [limits] are wrong."""
    w = np.asarray(model.spec.limits["tau_max"], dtype=float)
    peak = np.abs(log.tau).max(axis=0)
    i = int(np.argmax(peak / w))
    if peak[i] > TORQUE_SCALE_LIMIT * w[i]:
        raise LogError(f"{log.source}: column tau{i + 1} reaches {peak[i]:.4g}, "
                       f"{peak[i] / w[i]:.3g} times the model's tau_max of {w[i]:g} N m: torques "
                       f"must be in N m (a log in mN m is 1000 times too large), or the model "
                       f"file's [limits] tau_max is not this robot's")


def _check_signs(src, ls, nominal_base, names):
    """LogError if every well-determined base parameter (|estimate| > 2 sigma) has the opposite
    sign of the nominal model's: a reversed torque (or angle) convention, not a robot."""
    est, std = ls["estimate"], ls["std"]
    sure = (np.abs(est) > 2 * std) & (nominal_base != 0)
    flipped = np.sign(est) == -np.sign(nominal_base)
    if sure.sum() >= 3 and flipped[sure].all():
        raise LogError(f"{src}: every well-determined base parameter ({int(sure.sum())} of "
                       f"{len(est)}, e.g. {names[int(np.argmax(sure))]} = "
                       f"{est[int(np.argmax(sure))]:.4g} against the nominal "
                       f"{nominal_base[int(np.argmax(sure))]:.4g}) has the opposite sign of "
                       f"the model's: the torques' sign convention is probably reversed "
                       f"(tau_i must be positive in the direction of increasing qa_i)")


@dataclass(frozen=True, eq=False)
class Identification:
    """What :func:`identify_log` found in one log (r base parameters, p model parameters).

    Attributes
    ----------
    base : BaseParameters
        :func:`pm2dof.identification.base.base_parameters`.
    names : list of str
        The base parameters, readable (``alpha1 + 1 gamma2 + 1 gamma3``).
    independent_names : list of str
        The independent column each base parameter is named after.
    param_names : list of str
        The model's p parameter names.
    estimate, std : ndarray (r,)
        Weighted least squares and its 1 sigma (Newey-West).
    cov : ndarray (r, r)
        Its covariance.
    model_error : ndarray (3, r)
        :func:`model_error`: the shifts for :data:`MODEL_ERROR_CHOICES`.
    interval : ndarray (r,)
        The half-width 2 sigma + sum |model_error|.
    nominal : ndarray (r,)
        Tables 1-2, folded.
    theta_ls : ndarray (p,)
        Full theta from the estimate, the dependent parameters at nominal.
    consistent : dict or None
        :func:`pm2dof.identification.consistent.consistent_theta`, when computed.
    theta0 : ndarray (p,)
        The theta to use: the consistent one if computed, else ``theta_ls``.
    cutoff_hz : float
        Low-pass cutoff.
    band_hz : float or None
        The excitation band (None for a given cutoff); ``band_from`` says how it was found.
    band_from : str
    decimate : int
        Every r-th filtered sample kept.
    samples : int
        Samples used (equations / m).
    left_out_slow : int
        Samples left out for a joint slower than ``min_joint_speed`` (rad/s; linear
        actuators: times :data:`SPEED_LEVER`, m/s).
    min_joint_speed : float
    rms, r2 : ndarray (m,)
        Residual rms (N) and R^2 per task axis.
    lag1 : float
        Lag-1 autocorrelation of the residual.
    inflation : float
        Newey-West variance / OLS variance.
    condition_number : float
        Of the column-scaled regressor.
    duration_s : float
        The log's duration, s.
    warnings : tuple of str
    """
    base: object
    names: list
    independent_names: list
    param_names: list
    estimate: np.ndarray
    std: np.ndarray
    cov: np.ndarray
    model_error: np.ndarray
    interval: np.ndarray
    nominal: np.ndarray
    theta_ls: np.ndarray
    consistent: dict
    theta0: np.ndarray
    cutoff_hz: float
    band_hz: float
    band_from: str
    decimate: int
    samples: int
    left_out_slow: int
    min_joint_speed: float
    rms: np.ndarray
    r2: np.ndarray
    lag1: float
    inflation: float
    condition_number: float
    duration_s: float
    warnings: tuple


def identify_log(model, log, *, base=None, cutoff_hz=None, factor=CUTOFF_FACTOR,
                 decimate=None, min_joint_speed=MIN_JOINT_SPEED, consistent=True):
    """The whole pipeline on one log: base parameters with ±2 sigma, and a physical theta.

    Parameters
    ----------
    model : Model
    log : IdentLog
        Checked against the model by :func:`pm2dof.identification.log.log_poses`.
    base : BaseParameters, optional
        :func:`pm2dof.identification.base.base_parameters` (computed if not given).
    cutoff_hz : float, optional
        Low-pass cutoff, Hz (default :func:`choose_cutoff`: ``factor`` x the excitation band).
    factor : float
        The cutoff over the excitation's highest frequency when ``cutoff_hz`` is None
        (default ``CUTOFF_FACTOR``, 10).
    decimate : int, optional
        Keep every r-th filtered sample (default: 1 / (r T) >= 4 cutoff).
    min_joint_speed : float
        rad/s; samples with a slower active joint are left out (0: keep all). A linear
        actuator's threshold is this times :data:`SPEED_LEVER`, m/s (0.01 m/s by default).
    consistent : bool
        Also solve for a physically consistent full theta (CasADi + IPOPT).

    Returns
    -------
    Identification
        The estimate with its intervals, the physical theta (``theta0``), the filter, the
        residual statistics and the warnings.

    Raises
    ------
    LogError
        The log does not fit the model (see ``log_poses``), or is too short, or does not
        excite every base parameter (names the directions).
    """
    from .base import base_parameters
    base = base_parameters(model) if base is None else base
    inames = base.independent_names
    xe, _ = log_poses(model, log)
    _check_torque_scale(model, log)
    if cutoff_hz is None:
        cutoff_hz, band, how = choose_cutoff(log, xe, factor)
    else:
        band, how = None, "given"
    st = stack_regressor(model, base, log.t, xe, log.tau, cutoff_hz, decimate=decimate,
                         min_joint_speed=min_joint_speed)
    K = len(st["t"])
    r = base.r
    src = log.source
    if model.dof * K <= r:
        ms = (f"; the median step of t is {log.period:g} s: if t is in ms, it must be in s"
              if log.period >= 0.05 else "")
        raise LogError(f"{src}: too short to determine the {r} base parameters: {K} usable "
                       f"samples after the filter's edges ({st['edge']} samples each end), "
                       f"decimation by {st['decimate']} and {st['n_slow']} slow samples left out "
                       f"(a joint slower than {speed_phrase(model, min_joint_speed)}){ms}")
    Phi2 = st["Phi"].reshape(-1, r)
    cs = np.linalg.norm(Phi2, axis=0)
    sv = np.linalg.svd(Phi2 / np.where(cs > 0, cs, 1.0), compute_uv=False)
    if cs.min() == 0 or sv[-1] < 1e-8 * sv[0]:
        unseen = [n for n, c in zip(inames, cs) if c == 0] or ["(a combination; see the "
                                                             "condition number)"]
        raise LogError(f"{src}: the log does not excite every base parameter (too short or "
                       f"too little motion): column-scaled regressor condition number "
                       f"{sv[0] / max(sv[-1], 1e-300):.3g}; not seen: {', '.join(unseen)}")
    ls = weighted_ls(st["Phi"], st["u"])
    nominal = model.theta_nominal
    _check_signs(src, ls, base.fold(nominal), inames)
    theta_ls = base.unfold(ls["estimate"], nominal)
    shifts = model_error(model, base, log.t, xe, log.tau, cutoff_hz, min_joint_speed,
                         ls["estimate"])
    warnings = []
    if log.ignored:
        warnings.append(f"columns not used: {', '.join(log.ignored)}")
    for r2s, what in weak_directions(ls["cov"], ls["estimate"], inames,
                                     units=parameter_units(model, inames)):
        warnings.append(f"the data do not determine the direction {what} well (±2 sigma = "
                        f"{100 * r2s:.0f} % of its size): excite more, or trust it less")
    frac_slow = st["n_slow"] / max(st["n_candidates"], 1)
    if frac_slow > 0.75:
        warnings.append(f"{100 * frac_slow:.0f} % of the samples were left out because a joint "
                        f"moved slower than {speed_phrase(model, min_joint_speed)}: the "
                        f"estimate rests on "
                        f"few samples; a faster or richer excitation helps")
    sat = np.abs(log.tau) >= 0.999 * np.asarray(model.spec.limits["tau_max"])
    if sat.any():
        warnings.append(f"{int(sat.any(axis=1).sum())} rows have a torque at its limit "
                        f"(tau_max): if the drive clipped it, the logged torque is not the "
                        f"applied one")
    c = None
    if consistent:
        from .consistent import consistent_theta
        c = consistent_theta(ls["A"], ls["b"], base, nominal)
        if any(not s.startswith(("Solve_Succeeded", "Solved_To_Acceptable", "not needed"))
               for s in c["status"]):
            warnings.append(f"IPOPT: {c['status']}: the physical theta may not be optimal")
    return Identification(
        base=base, names=base.labels(), independent_names=inames, param_names=list(base.names),
        estimate=ls["estimate"], std=ls["std"], cov=ls["cov"], model_error=shifts,
        interval=2 * ls["std"] + np.abs(shifts).sum(axis=0), nominal=base.fold(nominal),
        theta_ls=theta_ls, consistent=c, theta0=theta_ls if c is None else c["theta"],
        cutoff_hz=float(cutoff_hz), band_hz=band, band_from=how, decimate=st["decimate"],
        samples=K, left_out_slow=st["n_slow"], min_joint_speed=min_joint_speed, rms=ls["rms"],
        r2=ls["r2"], lag1=ls["lag1"], inflation=ls["inflation"],
        condition_number=float(sv[0] / sv[-1]), duration_s=log.duration,
        warnings=tuple(warnings))

/* pm2dof generated code for model 'fivebar' (2 legs, friction 'coulomb_viscous').
 * Written by `pm2dof derive` from the model file; do not edit.
 *
 * Every function follows CasADi's C API: int f(const double** arg, double** res,
 * long long* iw, double* w, int mem), with work sizes from f_work(). All inputs and
 * outputs are dense; matrices are stored ROW-MAJOR (flattened row by row). SI units.
 *
 * q     = [qa_1..qa_2, qb_1..qb_2]  absolute joint angles, rad (eq. 3 order)
 * qa    = [qa_1..qa_2]  measured active angles, rad
 * xe    = [x, y] end-effector position, m;  xed, xrd, xrdd: velocities m/s, accel. m/s^2
 * theta = [alpha1, alpha2, beta1, beta2, gamma1, gamma2, fv1, fv2, fc1, fc2]
 *         (alpha, beta, gamma in kg*m^2; fv in N*m*s/rad; fc, fs in N*m)
 * sing  = [min_i |sin(qb_i - qa_i)| (type I, legs), sqrt(1 - |sum_i exp(2 i qb_i)| / n)
 *         (type II, actuation: sigma_min of S with unit rows over sqrt(n/2))]
 *
 * Functions (inputs -> outputs, element counts):
 *   fivebar_ik(xe[2]) -> (q[4])
 *   fivebar_fk(qa[2]) -> (xe[2], residual[2])
 *   fivebar_H(q[4]) -> (H[2])
 *   fivebar_A(q[4]) -> (A[8])
 *   fivebar_singularity(q[4]) -> (sin_ab[2])
 *   fivebar_singularity_measures(q[4]) -> (sing[2])
 *   fivebar_W(q[4]) -> (W[8], sing[2])
 *   fivebar_S(q[4]) -> (S[4], sing[2])
 *   fivebar_Wdot(q[4], xed[2]) -> (Wdot[8], sing[2])
 *   fivebar_M(q[4], theta[10]) -> (M[16])
 *   fivebar_C(q[4], qd[4], theta[10]) -> (C[16])
 *   fivebar_Me(q[4], theta[10]) -> (Me[4], sing[2])
 *   fivebar_Ce(q[4], xed[2], theta[10]) -> (Ce[4], sing[2])
 *   fivebar_StF(q[4], xed[2], theta[10]) -> (StF[2], sing[2])
 *   fivebar_Y(q[4], xed[2], xrd[2], xrdd[2]) -> (Y[20], sing[2])
 *   fivebar_torque_splits(q[4], u[2], tau_max[2], preload_sign[2], preload[2]) -> (tau_min_norm[2], tau_min_max[2], min_max_ratio[1], tau_preload[2], preload_mode[1], sing[2])
 *   fivebar_forward_dynamics(xe[2], xed[2], tau_a[2], theta[10]) -> (xedd[2], sing[2])
 *   fivebar_na_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[26]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_na_minmax_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[26]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_na_preload_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[26]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_na_proj_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[26]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_na_proj_minmax_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[26]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_na_proj_preload_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[26]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_apd_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[15]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_apd_minmax_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[15]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_apd_preload_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[15]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_ctc_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[15]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_ctc_minmax_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[15]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_ctc_preload_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[15]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_lqr_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[11], K[8], tau_ff[2]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_lqr_minmax_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[11], K[8], tau_ff[2]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_lqr_preload_step(state[14], qa[2], xd[2], xd_dot[2], xd_ddot[2], params[11], K[8], tau_ff[2]) -> (tau_a[2], state_next[14], status[1], diag[10])
 *   fivebar_plant_xedd(xe[2], xed[2], tau_a[2], plant[15]) -> (xedd[2])
 *   fivebar_plant_step(x[4], tau_a[2], plant[15], h[1]) -> (x_next[4])
 *   fivebar_measure(xe[2], plant[15]) -> (qa[2])
 *   fivebar_na_closed_loop(x[18], u[6], p[41]) -> (x_next[18], y[17])
 *   fivebar_na_minmax_closed_loop(x[18], u[6], p[41]) -> (x_next[18], y[17])
 *   fivebar_na_preload_closed_loop(x[18], u[6], p[41]) -> (x_next[18], y[17])
 *   fivebar_na_proj_closed_loop(x[18], u[6], p[41]) -> (x_next[18], y[17])
 *   fivebar_na_proj_minmax_closed_loop(x[18], u[6], p[41]) -> (x_next[18], y[17])
 *   fivebar_na_proj_preload_closed_loop(x[18], u[6], p[41]) -> (x_next[18], y[17])
 *   fivebar_apd_closed_loop(x[18], u[6], p[30]) -> (x_next[18], y[17])
 *   fivebar_apd_minmax_closed_loop(x[18], u[6], p[30]) -> (x_next[18], y[17])
 *   fivebar_apd_preload_closed_loop(x[18], u[6], p[30]) -> (x_next[18], y[17])
 *   fivebar_ctc_closed_loop(x[18], u[6], p[30]) -> (x_next[18], y[17])
 *   fivebar_ctc_minmax_closed_loop(x[18], u[6], p[30]) -> (x_next[18], y[17])
 *   fivebar_ctc_preload_closed_loop(x[18], u[6], p[30]) -> (x_next[18], y[17])
 *   fivebar_lqr_closed_loop(x[18], u[16], p[26]) -> (x_next[18], y[17])
 *   fivebar_lqr_minmax_closed_loop(x[18], u[16], p[26]) -> (x_next[18], y[17])
 *   fivebar_lqr_preload_closed_loop(x[18], u[16], p[26]) -> (x_next[18], y[17])
 *   fivebar_path_coefficients(p[2], dp[2], ddp[2], theta[10], tau_max[2]) -> (a[2], b[2], S[4], v1[2], N_min_norm[4], h_min_norm[2], N_min_max[4], h_min_max[2], sing[2])
 *   fivebar_path_mvc(stage[20], params[11]) -> (x_mvc[1])
 *   fivebar_path_backward(x_next_max[1], input[44], params[11]) -> (x_max[1], y[1])
 *   fivebar_path_forward(x[1], input[45], params[11]) -> (x_next[1], y[6])
 *   fivebar_path_torques(stage[20], sd[1], sdd[1], params[11], tau_max[2]) -> (u[2], tau_min_norm[2], tau_min_max[2], min_max_ratio[1])
 *   fivebar_forward_dynamics_jacobians(xe[2], xed[2], tau_a[2], theta[10]) -> (xedd[2], d_xe[4], d_xed[4], d_tau_a[4], d_theta[20], sing[2])
 *   fivebar_inverse_dynamics(xe[2], xed[2], xedd[2], theta[10]) -> (u[2], sing[2])
 *   fivebar_inverse_dynamics_jacobians(xe[2], xed[2], xedd[2], theta[10]) -> (u[2], d_xe[4], d_xed[4], sing[2])
 *   fivebar_sampled_step(x[4], tau_a[2], theta[10], T[1]) -> (x_next[4], sing[2])
 *   fivebar_sampled_step_jacobians(x[4], tau_a[2], theta[10], T[1]) -> (x_next[4], d_x[16], d_tau_a[8], sing[2])
 *   fivebar_Ge(q[4], theta[10]) -> (Ge[2], sing[2])
 *   fivebar_kinetic_energy(xe[2], xed[2], theta[10]) -> (T[1])
 *   fivebar_potential_energy(xe[2], theta[10]) -> (V[1])
 *
 * Flat vectors of the controllers, plant and closed loop (field[count], in order):
 *   ctrl_state: xe_prev[2], v[2], theta_hat[10]
 *   na_params: Kd[2], Q[2], Gamma[10], freeze_saturated[1], T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[2], preload_sign[2], preload[2], closure_tol[1]
 *   apd_params: Kp[2], Kv[2], T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[2], preload_sign[2], preload[2], closure_tol[1]
 *   ctc_params: Kp[2], Kv[2], T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[2], preload_sign[2], preload[2], closure_tol[1]
 *   lqr_params: T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[2], preload_sign[2], preload[2], closure_tol[1]
 *   cl_state: xe[2], xed[2], ctrl_state[14]
 *   cl_input: xd[2], xd_dot[2], xd_ddot[2]
 *   cl_output: xe[2], xed[2], tau_a[2], status[1], theta_hat[10]
 *   lqr_cl_input: xd[2], xd_dot[2], xd_ddot[2], K[8], tau_ff[2]
 *   plant: alpha[2], beta[2], gamma[2], fv[2], fc[2], fs[2], stribeck_velocity[1], coulomb_smoothing_velocity[1], encoder_step[1]
 *   path_stage: N[4], h[2], a[2], b[2], S[4], v1[2], rho[2], delta[1], x_cap[1]
 *   path_pair: stage[20], next[20], next_cap[1]
 *   path_backward_input: pair[41], same[1], x_in[1], x_out[1]
 *   path_forward_input: pair[41], x_next_max[1], same[1], x_in[1], x_out[1]
 *   path_forward_output: x[1], sdd[1], L[1], U[1], Z[1], arrival_ok[1]
 *   path_params: v_top[1], theta[10]
 *   status of a controller step: 0 ok, 1 singular, 2 saturated, 3 non_finite, 4 preload_infeasible, 5 inconsistent_encoders
 */
/* This file was automatically generated by CasADi 3.8.2.
 *  It consists of: 
 *   1) content generated by CasADi runtime: not copyrighted
 *   2) template code copied from CasADi source: permissively licensed (MIT-0)
 *   3) user code: owned by the user
 *
 */
#ifdef __cplusplus
extern "C" {
#endif

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int long long int
#endif

int fivebar_ik(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_ik_checkout(void);
void fivebar_ik_release(int mem);
void fivebar_ik_incref(void);
void fivebar_ik_decref(void);
casadi_int fivebar_ik_n_in(void);
casadi_int fivebar_ik_n_out(void);
casadi_real fivebar_ik_default_in(casadi_int i);
const char* fivebar_ik_name_in(casadi_int i);
const char* fivebar_ik_name_out(casadi_int i);
const casadi_int* fivebar_ik_sparsity_in(casadi_int i);
const casadi_int* fivebar_ik_sparsity_out(casadi_int i);
int fivebar_ik_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_ik_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_ik_SZ_ARG 1
#define fivebar_ik_SZ_RES 1
#define fivebar_ik_SZ_IW 0
#define fivebar_ik_SZ_W 0
int fivebar_fk(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_fk_checkout(void);
void fivebar_fk_release(int mem);
void fivebar_fk_incref(void);
void fivebar_fk_decref(void);
casadi_int fivebar_fk_n_in(void);
casadi_int fivebar_fk_n_out(void);
casadi_real fivebar_fk_default_in(casadi_int i);
const char* fivebar_fk_name_in(casadi_int i);
const char* fivebar_fk_name_out(casadi_int i);
const casadi_int* fivebar_fk_sparsity_in(casadi_int i);
const casadi_int* fivebar_fk_sparsity_out(casadi_int i);
int fivebar_fk_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_fk_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_fk_SZ_ARG 1
#define fivebar_fk_SZ_RES 2
#define fivebar_fk_SZ_IW 0
#define fivebar_fk_SZ_W 0
int fivebar_H(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_H_checkout(void);
void fivebar_H_release(int mem);
void fivebar_H_incref(void);
void fivebar_H_decref(void);
casadi_int fivebar_H_n_in(void);
casadi_int fivebar_H_n_out(void);
casadi_real fivebar_H_default_in(casadi_int i);
const char* fivebar_H_name_in(casadi_int i);
const char* fivebar_H_name_out(casadi_int i);
const casadi_int* fivebar_H_sparsity_in(casadi_int i);
const casadi_int* fivebar_H_sparsity_out(casadi_int i);
int fivebar_H_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_H_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_H_SZ_ARG 1
#define fivebar_H_SZ_RES 1
#define fivebar_H_SZ_IW 0
#define fivebar_H_SZ_W 0
int fivebar_A(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_A_checkout(void);
void fivebar_A_release(int mem);
void fivebar_A_incref(void);
void fivebar_A_decref(void);
casadi_int fivebar_A_n_in(void);
casadi_int fivebar_A_n_out(void);
casadi_real fivebar_A_default_in(casadi_int i);
const char* fivebar_A_name_in(casadi_int i);
const char* fivebar_A_name_out(casadi_int i);
const casadi_int* fivebar_A_sparsity_in(casadi_int i);
const casadi_int* fivebar_A_sparsity_out(casadi_int i);
int fivebar_A_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_A_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_A_SZ_ARG 1
#define fivebar_A_SZ_RES 1
#define fivebar_A_SZ_IW 0
#define fivebar_A_SZ_W 0
int fivebar_singularity(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_singularity_checkout(void);
void fivebar_singularity_release(int mem);
void fivebar_singularity_incref(void);
void fivebar_singularity_decref(void);
casadi_int fivebar_singularity_n_in(void);
casadi_int fivebar_singularity_n_out(void);
casadi_real fivebar_singularity_default_in(casadi_int i);
const char* fivebar_singularity_name_in(casadi_int i);
const char* fivebar_singularity_name_out(casadi_int i);
const casadi_int* fivebar_singularity_sparsity_in(casadi_int i);
const casadi_int* fivebar_singularity_sparsity_out(casadi_int i);
int fivebar_singularity_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_singularity_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_singularity_SZ_ARG 1
#define fivebar_singularity_SZ_RES 1
#define fivebar_singularity_SZ_IW 0
#define fivebar_singularity_SZ_W 0
int fivebar_singularity_measures(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_singularity_measures_checkout(void);
void fivebar_singularity_measures_release(int mem);
void fivebar_singularity_measures_incref(void);
void fivebar_singularity_measures_decref(void);
casadi_int fivebar_singularity_measures_n_in(void);
casadi_int fivebar_singularity_measures_n_out(void);
casadi_real fivebar_singularity_measures_default_in(casadi_int i);
const char* fivebar_singularity_measures_name_in(casadi_int i);
const char* fivebar_singularity_measures_name_out(casadi_int i);
const casadi_int* fivebar_singularity_measures_sparsity_in(casadi_int i);
const casadi_int* fivebar_singularity_measures_sparsity_out(casadi_int i);
int fivebar_singularity_measures_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_singularity_measures_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_singularity_measures_SZ_ARG 1
#define fivebar_singularity_measures_SZ_RES 1
#define fivebar_singularity_measures_SZ_IW 0
#define fivebar_singularity_measures_SZ_W 0
int fivebar_W(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_W_checkout(void);
void fivebar_W_release(int mem);
void fivebar_W_incref(void);
void fivebar_W_decref(void);
casadi_int fivebar_W_n_in(void);
casadi_int fivebar_W_n_out(void);
casadi_real fivebar_W_default_in(casadi_int i);
const char* fivebar_W_name_in(casadi_int i);
const char* fivebar_W_name_out(casadi_int i);
const casadi_int* fivebar_W_sparsity_in(casadi_int i);
const casadi_int* fivebar_W_sparsity_out(casadi_int i);
int fivebar_W_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_W_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_W_SZ_ARG 1
#define fivebar_W_SZ_RES 2
#define fivebar_W_SZ_IW 0
#define fivebar_W_SZ_W 0
int fivebar_S(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_S_checkout(void);
void fivebar_S_release(int mem);
void fivebar_S_incref(void);
void fivebar_S_decref(void);
casadi_int fivebar_S_n_in(void);
casadi_int fivebar_S_n_out(void);
casadi_real fivebar_S_default_in(casadi_int i);
const char* fivebar_S_name_in(casadi_int i);
const char* fivebar_S_name_out(casadi_int i);
const casadi_int* fivebar_S_sparsity_in(casadi_int i);
const casadi_int* fivebar_S_sparsity_out(casadi_int i);
int fivebar_S_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_S_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_S_SZ_ARG 1
#define fivebar_S_SZ_RES 2
#define fivebar_S_SZ_IW 0
#define fivebar_S_SZ_W 0
int fivebar_Wdot(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_Wdot_checkout(void);
void fivebar_Wdot_release(int mem);
void fivebar_Wdot_incref(void);
void fivebar_Wdot_decref(void);
casadi_int fivebar_Wdot_n_in(void);
casadi_int fivebar_Wdot_n_out(void);
casadi_real fivebar_Wdot_default_in(casadi_int i);
const char* fivebar_Wdot_name_in(casadi_int i);
const char* fivebar_Wdot_name_out(casadi_int i);
const casadi_int* fivebar_Wdot_sparsity_in(casadi_int i);
const casadi_int* fivebar_Wdot_sparsity_out(casadi_int i);
int fivebar_Wdot_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_Wdot_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_Wdot_SZ_ARG 2
#define fivebar_Wdot_SZ_RES 2
#define fivebar_Wdot_SZ_IW 0
#define fivebar_Wdot_SZ_W 0
int fivebar_M(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_M_checkout(void);
void fivebar_M_release(int mem);
void fivebar_M_incref(void);
void fivebar_M_decref(void);
casadi_int fivebar_M_n_in(void);
casadi_int fivebar_M_n_out(void);
casadi_real fivebar_M_default_in(casadi_int i);
const char* fivebar_M_name_in(casadi_int i);
const char* fivebar_M_name_out(casadi_int i);
const casadi_int* fivebar_M_sparsity_in(casadi_int i);
const casadi_int* fivebar_M_sparsity_out(casadi_int i);
int fivebar_M_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_M_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_M_SZ_ARG 2
#define fivebar_M_SZ_RES 1
#define fivebar_M_SZ_IW 0
#define fivebar_M_SZ_W 0
int fivebar_C(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_C_checkout(void);
void fivebar_C_release(int mem);
void fivebar_C_incref(void);
void fivebar_C_decref(void);
casadi_int fivebar_C_n_in(void);
casadi_int fivebar_C_n_out(void);
casadi_real fivebar_C_default_in(casadi_int i);
const char* fivebar_C_name_in(casadi_int i);
const char* fivebar_C_name_out(casadi_int i);
const casadi_int* fivebar_C_sparsity_in(casadi_int i);
const casadi_int* fivebar_C_sparsity_out(casadi_int i);
int fivebar_C_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_C_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_C_SZ_ARG 3
#define fivebar_C_SZ_RES 1
#define fivebar_C_SZ_IW 0
#define fivebar_C_SZ_W 0
int fivebar_Me(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_Me_checkout(void);
void fivebar_Me_release(int mem);
void fivebar_Me_incref(void);
void fivebar_Me_decref(void);
casadi_int fivebar_Me_n_in(void);
casadi_int fivebar_Me_n_out(void);
casadi_real fivebar_Me_default_in(casadi_int i);
const char* fivebar_Me_name_in(casadi_int i);
const char* fivebar_Me_name_out(casadi_int i);
const casadi_int* fivebar_Me_sparsity_in(casadi_int i);
const casadi_int* fivebar_Me_sparsity_out(casadi_int i);
int fivebar_Me_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_Me_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_Me_SZ_ARG 2
#define fivebar_Me_SZ_RES 2
#define fivebar_Me_SZ_IW 0
#define fivebar_Me_SZ_W 0
int fivebar_Ce(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_Ce_checkout(void);
void fivebar_Ce_release(int mem);
void fivebar_Ce_incref(void);
void fivebar_Ce_decref(void);
casadi_int fivebar_Ce_n_in(void);
casadi_int fivebar_Ce_n_out(void);
casadi_real fivebar_Ce_default_in(casadi_int i);
const char* fivebar_Ce_name_in(casadi_int i);
const char* fivebar_Ce_name_out(casadi_int i);
const casadi_int* fivebar_Ce_sparsity_in(casadi_int i);
const casadi_int* fivebar_Ce_sparsity_out(casadi_int i);
int fivebar_Ce_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_Ce_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_Ce_SZ_ARG 3
#define fivebar_Ce_SZ_RES 2
#define fivebar_Ce_SZ_IW 0
#define fivebar_Ce_SZ_W 0
int fivebar_StF(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_StF_checkout(void);
void fivebar_StF_release(int mem);
void fivebar_StF_incref(void);
void fivebar_StF_decref(void);
casadi_int fivebar_StF_n_in(void);
casadi_int fivebar_StF_n_out(void);
casadi_real fivebar_StF_default_in(casadi_int i);
const char* fivebar_StF_name_in(casadi_int i);
const char* fivebar_StF_name_out(casadi_int i);
const casadi_int* fivebar_StF_sparsity_in(casadi_int i);
const casadi_int* fivebar_StF_sparsity_out(casadi_int i);
int fivebar_StF_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_StF_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_StF_SZ_ARG 3
#define fivebar_StF_SZ_RES 2
#define fivebar_StF_SZ_IW 0
#define fivebar_StF_SZ_W 0
int fivebar_Y(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_Y_checkout(void);
void fivebar_Y_release(int mem);
void fivebar_Y_incref(void);
void fivebar_Y_decref(void);
casadi_int fivebar_Y_n_in(void);
casadi_int fivebar_Y_n_out(void);
casadi_real fivebar_Y_default_in(casadi_int i);
const char* fivebar_Y_name_in(casadi_int i);
const char* fivebar_Y_name_out(casadi_int i);
const casadi_int* fivebar_Y_sparsity_in(casadi_int i);
const casadi_int* fivebar_Y_sparsity_out(casadi_int i);
int fivebar_Y_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_Y_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_Y_SZ_ARG 4
#define fivebar_Y_SZ_RES 2
#define fivebar_Y_SZ_IW 0
#define fivebar_Y_SZ_W 0
int fivebar_torque_splits(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_torque_splits_checkout(void);
void fivebar_torque_splits_release(int mem);
void fivebar_torque_splits_incref(void);
void fivebar_torque_splits_decref(void);
casadi_int fivebar_torque_splits_n_in(void);
casadi_int fivebar_torque_splits_n_out(void);
casadi_real fivebar_torque_splits_default_in(casadi_int i);
const char* fivebar_torque_splits_name_in(casadi_int i);
const char* fivebar_torque_splits_name_out(casadi_int i);
const casadi_int* fivebar_torque_splits_sparsity_in(casadi_int i);
const casadi_int* fivebar_torque_splits_sparsity_out(casadi_int i);
int fivebar_torque_splits_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_torque_splits_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_torque_splits_SZ_ARG 10
#define fivebar_torque_splits_SZ_RES 8
#define fivebar_torque_splits_SZ_IW 0
#define fivebar_torque_splits_SZ_W 51
int fivebar_forward_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_forward_dynamics_checkout(void);
void fivebar_forward_dynamics_release(int mem);
void fivebar_forward_dynamics_incref(void);
void fivebar_forward_dynamics_decref(void);
casadi_int fivebar_forward_dynamics_n_in(void);
casadi_int fivebar_forward_dynamics_n_out(void);
casadi_real fivebar_forward_dynamics_default_in(casadi_int i);
const char* fivebar_forward_dynamics_name_in(casadi_int i);
const char* fivebar_forward_dynamics_name_out(casadi_int i);
const casadi_int* fivebar_forward_dynamics_sparsity_in(casadi_int i);
const casadi_int* fivebar_forward_dynamics_sparsity_out(casadi_int i);
int fivebar_forward_dynamics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_forward_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_forward_dynamics_SZ_ARG 4
#define fivebar_forward_dynamics_SZ_RES 2
#define fivebar_forward_dynamics_SZ_IW 0
#define fivebar_forward_dynamics_SZ_W 0
int fivebar_na_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_na_step_checkout(void);
void fivebar_na_step_release(int mem);
void fivebar_na_step_incref(void);
void fivebar_na_step_decref(void);
casadi_int fivebar_na_step_n_in(void);
casadi_int fivebar_na_step_n_out(void);
casadi_real fivebar_na_step_default_in(casadi_int i);
const char* fivebar_na_step_name_in(casadi_int i);
const char* fivebar_na_step_name_out(casadi_int i);
const casadi_int* fivebar_na_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_na_step_sparsity_out(casadi_int i);
int fivebar_na_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_na_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_na_step_SZ_ARG 6
#define fivebar_na_step_SZ_RES 4
#define fivebar_na_step_SZ_IW 0
#define fivebar_na_step_SZ_W 0
int fivebar_na_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_na_minmax_step_checkout(void);
void fivebar_na_minmax_step_release(int mem);
void fivebar_na_minmax_step_incref(void);
void fivebar_na_minmax_step_decref(void);
casadi_int fivebar_na_minmax_step_n_in(void);
casadi_int fivebar_na_minmax_step_n_out(void);
casadi_real fivebar_na_minmax_step_default_in(casadi_int i);
const char* fivebar_na_minmax_step_name_in(casadi_int i);
const char* fivebar_na_minmax_step_name_out(casadi_int i);
const casadi_int* fivebar_na_minmax_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_na_minmax_step_sparsity_out(casadi_int i);
int fivebar_na_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_na_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_na_minmax_step_SZ_ARG 6
#define fivebar_na_minmax_step_SZ_RES 4
#define fivebar_na_minmax_step_SZ_IW 0
#define fivebar_na_minmax_step_SZ_W 0
int fivebar_na_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_na_preload_step_checkout(void);
void fivebar_na_preload_step_release(int mem);
void fivebar_na_preload_step_incref(void);
void fivebar_na_preload_step_decref(void);
casadi_int fivebar_na_preload_step_n_in(void);
casadi_int fivebar_na_preload_step_n_out(void);
casadi_real fivebar_na_preload_step_default_in(casadi_int i);
const char* fivebar_na_preload_step_name_in(casadi_int i);
const char* fivebar_na_preload_step_name_out(casadi_int i);
const casadi_int* fivebar_na_preload_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_na_preload_step_sparsity_out(casadi_int i);
int fivebar_na_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_na_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_na_preload_step_SZ_ARG 11
#define fivebar_na_preload_step_SZ_RES 6
#define fivebar_na_preload_step_SZ_IW 0
#define fivebar_na_preload_step_SZ_W 51
int fivebar_na_proj_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_na_proj_step_checkout(void);
void fivebar_na_proj_step_release(int mem);
void fivebar_na_proj_step_incref(void);
void fivebar_na_proj_step_decref(void);
casadi_int fivebar_na_proj_step_n_in(void);
casadi_int fivebar_na_proj_step_n_out(void);
casadi_real fivebar_na_proj_step_default_in(casadi_int i);
const char* fivebar_na_proj_step_name_in(casadi_int i);
const char* fivebar_na_proj_step_name_out(casadi_int i);
const casadi_int* fivebar_na_proj_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_na_proj_step_sparsity_out(casadi_int i);
int fivebar_na_proj_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_na_proj_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_na_proj_step_SZ_ARG 6
#define fivebar_na_proj_step_SZ_RES 4
#define fivebar_na_proj_step_SZ_IW 0
#define fivebar_na_proj_step_SZ_W 0
int fivebar_na_proj_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_na_proj_minmax_step_checkout(void);
void fivebar_na_proj_minmax_step_release(int mem);
void fivebar_na_proj_minmax_step_incref(void);
void fivebar_na_proj_minmax_step_decref(void);
casadi_int fivebar_na_proj_minmax_step_n_in(void);
casadi_int fivebar_na_proj_minmax_step_n_out(void);
casadi_real fivebar_na_proj_minmax_step_default_in(casadi_int i);
const char* fivebar_na_proj_minmax_step_name_in(casadi_int i);
const char* fivebar_na_proj_minmax_step_name_out(casadi_int i);
const casadi_int* fivebar_na_proj_minmax_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_na_proj_minmax_step_sparsity_out(casadi_int i);
int fivebar_na_proj_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_na_proj_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_na_proj_minmax_step_SZ_ARG 6
#define fivebar_na_proj_minmax_step_SZ_RES 4
#define fivebar_na_proj_minmax_step_SZ_IW 0
#define fivebar_na_proj_minmax_step_SZ_W 0
int fivebar_na_proj_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_na_proj_preload_step_checkout(void);
void fivebar_na_proj_preload_step_release(int mem);
void fivebar_na_proj_preload_step_incref(void);
void fivebar_na_proj_preload_step_decref(void);
casadi_int fivebar_na_proj_preload_step_n_in(void);
casadi_int fivebar_na_proj_preload_step_n_out(void);
casadi_real fivebar_na_proj_preload_step_default_in(casadi_int i);
const char* fivebar_na_proj_preload_step_name_in(casadi_int i);
const char* fivebar_na_proj_preload_step_name_out(casadi_int i);
const casadi_int* fivebar_na_proj_preload_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_na_proj_preload_step_sparsity_out(casadi_int i);
int fivebar_na_proj_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_na_proj_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_na_proj_preload_step_SZ_ARG 11
#define fivebar_na_proj_preload_step_SZ_RES 6
#define fivebar_na_proj_preload_step_SZ_IW 0
#define fivebar_na_proj_preload_step_SZ_W 51
int fivebar_apd_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_apd_step_checkout(void);
void fivebar_apd_step_release(int mem);
void fivebar_apd_step_incref(void);
void fivebar_apd_step_decref(void);
casadi_int fivebar_apd_step_n_in(void);
casadi_int fivebar_apd_step_n_out(void);
casadi_real fivebar_apd_step_default_in(casadi_int i);
const char* fivebar_apd_step_name_in(casadi_int i);
const char* fivebar_apd_step_name_out(casadi_int i);
const casadi_int* fivebar_apd_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_apd_step_sparsity_out(casadi_int i);
int fivebar_apd_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_apd_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_apd_step_SZ_ARG 6
#define fivebar_apd_step_SZ_RES 4
#define fivebar_apd_step_SZ_IW 0
#define fivebar_apd_step_SZ_W 0
int fivebar_apd_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_apd_minmax_step_checkout(void);
void fivebar_apd_minmax_step_release(int mem);
void fivebar_apd_minmax_step_incref(void);
void fivebar_apd_minmax_step_decref(void);
casadi_int fivebar_apd_minmax_step_n_in(void);
casadi_int fivebar_apd_minmax_step_n_out(void);
casadi_real fivebar_apd_minmax_step_default_in(casadi_int i);
const char* fivebar_apd_minmax_step_name_in(casadi_int i);
const char* fivebar_apd_minmax_step_name_out(casadi_int i);
const casadi_int* fivebar_apd_minmax_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_apd_minmax_step_sparsity_out(casadi_int i);
int fivebar_apd_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_apd_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_apd_minmax_step_SZ_ARG 6
#define fivebar_apd_minmax_step_SZ_RES 4
#define fivebar_apd_minmax_step_SZ_IW 0
#define fivebar_apd_minmax_step_SZ_W 0
int fivebar_apd_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_apd_preload_step_checkout(void);
void fivebar_apd_preload_step_release(int mem);
void fivebar_apd_preload_step_incref(void);
void fivebar_apd_preload_step_decref(void);
casadi_int fivebar_apd_preload_step_n_in(void);
casadi_int fivebar_apd_preload_step_n_out(void);
casadi_real fivebar_apd_preload_step_default_in(casadi_int i);
const char* fivebar_apd_preload_step_name_in(casadi_int i);
const char* fivebar_apd_preload_step_name_out(casadi_int i);
const casadi_int* fivebar_apd_preload_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_apd_preload_step_sparsity_out(casadi_int i);
int fivebar_apd_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_apd_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_apd_preload_step_SZ_ARG 11
#define fivebar_apd_preload_step_SZ_RES 6
#define fivebar_apd_preload_step_SZ_IW 0
#define fivebar_apd_preload_step_SZ_W 51
int fivebar_ctc_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_ctc_step_checkout(void);
void fivebar_ctc_step_release(int mem);
void fivebar_ctc_step_incref(void);
void fivebar_ctc_step_decref(void);
casadi_int fivebar_ctc_step_n_in(void);
casadi_int fivebar_ctc_step_n_out(void);
casadi_real fivebar_ctc_step_default_in(casadi_int i);
const char* fivebar_ctc_step_name_in(casadi_int i);
const char* fivebar_ctc_step_name_out(casadi_int i);
const casadi_int* fivebar_ctc_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_ctc_step_sparsity_out(casadi_int i);
int fivebar_ctc_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_ctc_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_ctc_step_SZ_ARG 6
#define fivebar_ctc_step_SZ_RES 4
#define fivebar_ctc_step_SZ_IW 0
#define fivebar_ctc_step_SZ_W 0
int fivebar_ctc_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_ctc_minmax_step_checkout(void);
void fivebar_ctc_minmax_step_release(int mem);
void fivebar_ctc_minmax_step_incref(void);
void fivebar_ctc_minmax_step_decref(void);
casadi_int fivebar_ctc_minmax_step_n_in(void);
casadi_int fivebar_ctc_minmax_step_n_out(void);
casadi_real fivebar_ctc_minmax_step_default_in(casadi_int i);
const char* fivebar_ctc_minmax_step_name_in(casadi_int i);
const char* fivebar_ctc_minmax_step_name_out(casadi_int i);
const casadi_int* fivebar_ctc_minmax_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_ctc_minmax_step_sparsity_out(casadi_int i);
int fivebar_ctc_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_ctc_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_ctc_minmax_step_SZ_ARG 6
#define fivebar_ctc_minmax_step_SZ_RES 4
#define fivebar_ctc_minmax_step_SZ_IW 0
#define fivebar_ctc_minmax_step_SZ_W 0
int fivebar_ctc_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_ctc_preload_step_checkout(void);
void fivebar_ctc_preload_step_release(int mem);
void fivebar_ctc_preload_step_incref(void);
void fivebar_ctc_preload_step_decref(void);
casadi_int fivebar_ctc_preload_step_n_in(void);
casadi_int fivebar_ctc_preload_step_n_out(void);
casadi_real fivebar_ctc_preload_step_default_in(casadi_int i);
const char* fivebar_ctc_preload_step_name_in(casadi_int i);
const char* fivebar_ctc_preload_step_name_out(casadi_int i);
const casadi_int* fivebar_ctc_preload_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_ctc_preload_step_sparsity_out(casadi_int i);
int fivebar_ctc_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_ctc_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_ctc_preload_step_SZ_ARG 11
#define fivebar_ctc_preload_step_SZ_RES 6
#define fivebar_ctc_preload_step_SZ_IW 0
#define fivebar_ctc_preload_step_SZ_W 51
int fivebar_lqr_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_lqr_step_checkout(void);
void fivebar_lqr_step_release(int mem);
void fivebar_lqr_step_incref(void);
void fivebar_lqr_step_decref(void);
casadi_int fivebar_lqr_step_n_in(void);
casadi_int fivebar_lqr_step_n_out(void);
casadi_real fivebar_lqr_step_default_in(casadi_int i);
const char* fivebar_lqr_step_name_in(casadi_int i);
const char* fivebar_lqr_step_name_out(casadi_int i);
const casadi_int* fivebar_lqr_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_lqr_step_sparsity_out(casadi_int i);
int fivebar_lqr_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_lqr_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_lqr_step_SZ_ARG 8
#define fivebar_lqr_step_SZ_RES 4
#define fivebar_lqr_step_SZ_IW 0
#define fivebar_lqr_step_SZ_W 0
int fivebar_lqr_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_lqr_minmax_step_checkout(void);
void fivebar_lqr_minmax_step_release(int mem);
void fivebar_lqr_minmax_step_incref(void);
void fivebar_lqr_minmax_step_decref(void);
casadi_int fivebar_lqr_minmax_step_n_in(void);
casadi_int fivebar_lqr_minmax_step_n_out(void);
casadi_real fivebar_lqr_minmax_step_default_in(casadi_int i);
const char* fivebar_lqr_minmax_step_name_in(casadi_int i);
const char* fivebar_lqr_minmax_step_name_out(casadi_int i);
const casadi_int* fivebar_lqr_minmax_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_lqr_minmax_step_sparsity_out(casadi_int i);
int fivebar_lqr_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_lqr_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_lqr_minmax_step_SZ_ARG 8
#define fivebar_lqr_minmax_step_SZ_RES 4
#define fivebar_lqr_minmax_step_SZ_IW 0
#define fivebar_lqr_minmax_step_SZ_W 0
int fivebar_lqr_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_lqr_preload_step_checkout(void);
void fivebar_lqr_preload_step_release(int mem);
void fivebar_lqr_preload_step_incref(void);
void fivebar_lqr_preload_step_decref(void);
casadi_int fivebar_lqr_preload_step_n_in(void);
casadi_int fivebar_lqr_preload_step_n_out(void);
casadi_real fivebar_lqr_preload_step_default_in(casadi_int i);
const char* fivebar_lqr_preload_step_name_in(casadi_int i);
const char* fivebar_lqr_preload_step_name_out(casadi_int i);
const casadi_int* fivebar_lqr_preload_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_lqr_preload_step_sparsity_out(casadi_int i);
int fivebar_lqr_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_lqr_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_lqr_preload_step_SZ_ARG 13
#define fivebar_lqr_preload_step_SZ_RES 6
#define fivebar_lqr_preload_step_SZ_IW 0
#define fivebar_lqr_preload_step_SZ_W 51
int fivebar_plant_xedd(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_plant_xedd_checkout(void);
void fivebar_plant_xedd_release(int mem);
void fivebar_plant_xedd_incref(void);
void fivebar_plant_xedd_decref(void);
casadi_int fivebar_plant_xedd_n_in(void);
casadi_int fivebar_plant_xedd_n_out(void);
casadi_real fivebar_plant_xedd_default_in(casadi_int i);
const char* fivebar_plant_xedd_name_in(casadi_int i);
const char* fivebar_plant_xedd_name_out(casadi_int i);
const casadi_int* fivebar_plant_xedd_sparsity_in(casadi_int i);
const casadi_int* fivebar_plant_xedd_sparsity_out(casadi_int i);
int fivebar_plant_xedd_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_plant_xedd_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_plant_xedd_SZ_ARG 4
#define fivebar_plant_xedd_SZ_RES 1
#define fivebar_plant_xedd_SZ_IW 0
#define fivebar_plant_xedd_SZ_W 0
int fivebar_plant_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_plant_step_checkout(void);
void fivebar_plant_step_release(int mem);
void fivebar_plant_step_incref(void);
void fivebar_plant_step_decref(void);
casadi_int fivebar_plant_step_n_in(void);
casadi_int fivebar_plant_step_n_out(void);
casadi_real fivebar_plant_step_default_in(casadi_int i);
const char* fivebar_plant_step_name_in(casadi_int i);
const char* fivebar_plant_step_name_out(casadi_int i);
const casadi_int* fivebar_plant_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_plant_step_sparsity_out(casadi_int i);
int fivebar_plant_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_plant_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_plant_step_SZ_ARG 4
#define fivebar_plant_step_SZ_RES 1
#define fivebar_plant_step_SZ_IW 0
#define fivebar_plant_step_SZ_W 0
int fivebar_measure(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_measure_checkout(void);
void fivebar_measure_release(int mem);
void fivebar_measure_incref(void);
void fivebar_measure_decref(void);
casadi_int fivebar_measure_n_in(void);
casadi_int fivebar_measure_n_out(void);
casadi_real fivebar_measure_default_in(casadi_int i);
const char* fivebar_measure_name_in(casadi_int i);
const char* fivebar_measure_name_out(casadi_int i);
const casadi_int* fivebar_measure_sparsity_in(casadi_int i);
const casadi_int* fivebar_measure_sparsity_out(casadi_int i);
int fivebar_measure_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_measure_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_measure_SZ_ARG 2
#define fivebar_measure_SZ_RES 1
#define fivebar_measure_SZ_IW 0
#define fivebar_measure_SZ_W 0
int fivebar_na_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_na_closed_loop_checkout(void);
void fivebar_na_closed_loop_release(int mem);
void fivebar_na_closed_loop_incref(void);
void fivebar_na_closed_loop_decref(void);
casadi_int fivebar_na_closed_loop_n_in(void);
casadi_int fivebar_na_closed_loop_n_out(void);
casadi_real fivebar_na_closed_loop_default_in(casadi_int i);
const char* fivebar_na_closed_loop_name_in(casadi_int i);
const char* fivebar_na_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_na_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_na_closed_loop_sparsity_out(casadi_int i);
int fivebar_na_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_na_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_na_closed_loop_SZ_ARG 9
#define fivebar_na_closed_loop_SZ_RES 6
#define fivebar_na_closed_loop_SZ_IW 0
#define fivebar_na_closed_loop_SZ_W 121
int fivebar_na_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_na_minmax_closed_loop_checkout(void);
void fivebar_na_minmax_closed_loop_release(int mem);
void fivebar_na_minmax_closed_loop_incref(void);
void fivebar_na_minmax_closed_loop_decref(void);
casadi_int fivebar_na_minmax_closed_loop_n_in(void);
casadi_int fivebar_na_minmax_closed_loop_n_out(void);
casadi_real fivebar_na_minmax_closed_loop_default_in(casadi_int i);
const char* fivebar_na_minmax_closed_loop_name_in(casadi_int i);
const char* fivebar_na_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_na_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_na_minmax_closed_loop_sparsity_out(casadi_int i);
int fivebar_na_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_na_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_na_minmax_closed_loop_SZ_ARG 9
#define fivebar_na_minmax_closed_loop_SZ_RES 6
#define fivebar_na_minmax_closed_loop_SZ_IW 0
#define fivebar_na_minmax_closed_loop_SZ_W 121
int fivebar_na_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_na_preload_closed_loop_checkout(void);
void fivebar_na_preload_closed_loop_release(int mem);
void fivebar_na_preload_closed_loop_incref(void);
void fivebar_na_preload_closed_loop_decref(void);
casadi_int fivebar_na_preload_closed_loop_n_in(void);
casadi_int fivebar_na_preload_closed_loop_n_out(void);
casadi_real fivebar_na_preload_closed_loop_default_in(casadi_int i);
const char* fivebar_na_preload_closed_loop_name_in(casadi_int i);
const char* fivebar_na_preload_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_na_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_na_preload_closed_loop_sparsity_out(casadi_int i);
int fivebar_na_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_na_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_na_preload_closed_loop_SZ_ARG 14
#define fivebar_na_preload_closed_loop_SZ_RES 8
#define fivebar_na_preload_closed_loop_SZ_IW 0
#define fivebar_na_preload_closed_loop_SZ_W 164
int fivebar_na_proj_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_na_proj_closed_loop_checkout(void);
void fivebar_na_proj_closed_loop_release(int mem);
void fivebar_na_proj_closed_loop_incref(void);
void fivebar_na_proj_closed_loop_decref(void);
casadi_int fivebar_na_proj_closed_loop_n_in(void);
casadi_int fivebar_na_proj_closed_loop_n_out(void);
casadi_real fivebar_na_proj_closed_loop_default_in(casadi_int i);
const char* fivebar_na_proj_closed_loop_name_in(casadi_int i);
const char* fivebar_na_proj_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_na_proj_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_na_proj_closed_loop_sparsity_out(casadi_int i);
int fivebar_na_proj_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_na_proj_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_na_proj_closed_loop_SZ_ARG 9
#define fivebar_na_proj_closed_loop_SZ_RES 6
#define fivebar_na_proj_closed_loop_SZ_IW 0
#define fivebar_na_proj_closed_loop_SZ_W 121
int fivebar_na_proj_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_na_proj_minmax_closed_loop_checkout(void);
void fivebar_na_proj_minmax_closed_loop_release(int mem);
void fivebar_na_proj_minmax_closed_loop_incref(void);
void fivebar_na_proj_minmax_closed_loop_decref(void);
casadi_int fivebar_na_proj_minmax_closed_loop_n_in(void);
casadi_int fivebar_na_proj_minmax_closed_loop_n_out(void);
casadi_real fivebar_na_proj_minmax_closed_loop_default_in(casadi_int i);
const char* fivebar_na_proj_minmax_closed_loop_name_in(casadi_int i);
const char* fivebar_na_proj_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_na_proj_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_na_proj_minmax_closed_loop_sparsity_out(casadi_int i);
int fivebar_na_proj_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_na_proj_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_na_proj_minmax_closed_loop_SZ_ARG 9
#define fivebar_na_proj_minmax_closed_loop_SZ_RES 6
#define fivebar_na_proj_minmax_closed_loop_SZ_IW 0
#define fivebar_na_proj_minmax_closed_loop_SZ_W 121
int fivebar_na_proj_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_na_proj_preload_closed_loop_checkout(void);
void fivebar_na_proj_preload_closed_loop_release(int mem);
void fivebar_na_proj_preload_closed_loop_incref(void);
void fivebar_na_proj_preload_closed_loop_decref(void);
casadi_int fivebar_na_proj_preload_closed_loop_n_in(void);
casadi_int fivebar_na_proj_preload_closed_loop_n_out(void);
casadi_real fivebar_na_proj_preload_closed_loop_default_in(casadi_int i);
const char* fivebar_na_proj_preload_closed_loop_name_in(casadi_int i);
const char* fivebar_na_proj_preload_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_na_proj_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_na_proj_preload_closed_loop_sparsity_out(casadi_int i);
int fivebar_na_proj_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_na_proj_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_na_proj_preload_closed_loop_SZ_ARG 14
#define fivebar_na_proj_preload_closed_loop_SZ_RES 8
#define fivebar_na_proj_preload_closed_loop_SZ_IW 0
#define fivebar_na_proj_preload_closed_loop_SZ_W 164
int fivebar_apd_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_apd_closed_loop_checkout(void);
void fivebar_apd_closed_loop_release(int mem);
void fivebar_apd_closed_loop_incref(void);
void fivebar_apd_closed_loop_decref(void);
casadi_int fivebar_apd_closed_loop_n_in(void);
casadi_int fivebar_apd_closed_loop_n_out(void);
casadi_real fivebar_apd_closed_loop_default_in(casadi_int i);
const char* fivebar_apd_closed_loop_name_in(casadi_int i);
const char* fivebar_apd_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_apd_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_apd_closed_loop_sparsity_out(casadi_int i);
int fivebar_apd_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_apd_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_apd_closed_loop_SZ_ARG 9
#define fivebar_apd_closed_loop_SZ_RES 6
#define fivebar_apd_closed_loop_SZ_IW 0
#define fivebar_apd_closed_loop_SZ_W 121
int fivebar_apd_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_apd_minmax_closed_loop_checkout(void);
void fivebar_apd_minmax_closed_loop_release(int mem);
void fivebar_apd_minmax_closed_loop_incref(void);
void fivebar_apd_minmax_closed_loop_decref(void);
casadi_int fivebar_apd_minmax_closed_loop_n_in(void);
casadi_int fivebar_apd_minmax_closed_loop_n_out(void);
casadi_real fivebar_apd_minmax_closed_loop_default_in(casadi_int i);
const char* fivebar_apd_minmax_closed_loop_name_in(casadi_int i);
const char* fivebar_apd_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_apd_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_apd_minmax_closed_loop_sparsity_out(casadi_int i);
int fivebar_apd_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_apd_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_apd_minmax_closed_loop_SZ_ARG 9
#define fivebar_apd_minmax_closed_loop_SZ_RES 6
#define fivebar_apd_minmax_closed_loop_SZ_IW 0
#define fivebar_apd_minmax_closed_loop_SZ_W 121
int fivebar_apd_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_apd_preload_closed_loop_checkout(void);
void fivebar_apd_preload_closed_loop_release(int mem);
void fivebar_apd_preload_closed_loop_incref(void);
void fivebar_apd_preload_closed_loop_decref(void);
casadi_int fivebar_apd_preload_closed_loop_n_in(void);
casadi_int fivebar_apd_preload_closed_loop_n_out(void);
casadi_real fivebar_apd_preload_closed_loop_default_in(casadi_int i);
const char* fivebar_apd_preload_closed_loop_name_in(casadi_int i);
const char* fivebar_apd_preload_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_apd_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_apd_preload_closed_loop_sparsity_out(casadi_int i);
int fivebar_apd_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_apd_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_apd_preload_closed_loop_SZ_ARG 14
#define fivebar_apd_preload_closed_loop_SZ_RES 8
#define fivebar_apd_preload_closed_loop_SZ_IW 0
#define fivebar_apd_preload_closed_loop_SZ_W 157
int fivebar_ctc_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_ctc_closed_loop_checkout(void);
void fivebar_ctc_closed_loop_release(int mem);
void fivebar_ctc_closed_loop_incref(void);
void fivebar_ctc_closed_loop_decref(void);
casadi_int fivebar_ctc_closed_loop_n_in(void);
casadi_int fivebar_ctc_closed_loop_n_out(void);
casadi_real fivebar_ctc_closed_loop_default_in(casadi_int i);
const char* fivebar_ctc_closed_loop_name_in(casadi_int i);
const char* fivebar_ctc_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_ctc_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_ctc_closed_loop_sparsity_out(casadi_int i);
int fivebar_ctc_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_ctc_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_ctc_closed_loop_SZ_ARG 9
#define fivebar_ctc_closed_loop_SZ_RES 6
#define fivebar_ctc_closed_loop_SZ_IW 0
#define fivebar_ctc_closed_loop_SZ_W 121
int fivebar_ctc_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_ctc_minmax_closed_loop_checkout(void);
void fivebar_ctc_minmax_closed_loop_release(int mem);
void fivebar_ctc_minmax_closed_loop_incref(void);
void fivebar_ctc_minmax_closed_loop_decref(void);
casadi_int fivebar_ctc_minmax_closed_loop_n_in(void);
casadi_int fivebar_ctc_minmax_closed_loop_n_out(void);
casadi_real fivebar_ctc_minmax_closed_loop_default_in(casadi_int i);
const char* fivebar_ctc_minmax_closed_loop_name_in(casadi_int i);
const char* fivebar_ctc_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_ctc_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_ctc_minmax_closed_loop_sparsity_out(casadi_int i);
int fivebar_ctc_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_ctc_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_ctc_minmax_closed_loop_SZ_ARG 9
#define fivebar_ctc_minmax_closed_loop_SZ_RES 6
#define fivebar_ctc_minmax_closed_loop_SZ_IW 0
#define fivebar_ctc_minmax_closed_loop_SZ_W 121
int fivebar_ctc_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_ctc_preload_closed_loop_checkout(void);
void fivebar_ctc_preload_closed_loop_release(int mem);
void fivebar_ctc_preload_closed_loop_incref(void);
void fivebar_ctc_preload_closed_loop_decref(void);
casadi_int fivebar_ctc_preload_closed_loop_n_in(void);
casadi_int fivebar_ctc_preload_closed_loop_n_out(void);
casadi_real fivebar_ctc_preload_closed_loop_default_in(casadi_int i);
const char* fivebar_ctc_preload_closed_loop_name_in(casadi_int i);
const char* fivebar_ctc_preload_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_ctc_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_ctc_preload_closed_loop_sparsity_out(casadi_int i);
int fivebar_ctc_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_ctc_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_ctc_preload_closed_loop_SZ_ARG 14
#define fivebar_ctc_preload_closed_loop_SZ_RES 8
#define fivebar_ctc_preload_closed_loop_SZ_IW 0
#define fivebar_ctc_preload_closed_loop_SZ_W 155
int fivebar_lqr_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_lqr_closed_loop_checkout(void);
void fivebar_lqr_closed_loop_release(int mem);
void fivebar_lqr_closed_loop_incref(void);
void fivebar_lqr_closed_loop_decref(void);
casadi_int fivebar_lqr_closed_loop_n_in(void);
casadi_int fivebar_lqr_closed_loop_n_out(void);
casadi_real fivebar_lqr_closed_loop_default_in(casadi_int i);
const char* fivebar_lqr_closed_loop_name_in(casadi_int i);
const char* fivebar_lqr_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_lqr_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_lqr_closed_loop_sparsity_out(casadi_int i);
int fivebar_lqr_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_lqr_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_lqr_closed_loop_SZ_ARG 11
#define fivebar_lqr_closed_loop_SZ_RES 6
#define fivebar_lqr_closed_loop_SZ_IW 0
#define fivebar_lqr_closed_loop_SZ_W 109
int fivebar_lqr_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_lqr_minmax_closed_loop_checkout(void);
void fivebar_lqr_minmax_closed_loop_release(int mem);
void fivebar_lqr_minmax_closed_loop_incref(void);
void fivebar_lqr_minmax_closed_loop_decref(void);
casadi_int fivebar_lqr_minmax_closed_loop_n_in(void);
casadi_int fivebar_lqr_minmax_closed_loop_n_out(void);
casadi_real fivebar_lqr_minmax_closed_loop_default_in(casadi_int i);
const char* fivebar_lqr_minmax_closed_loop_name_in(casadi_int i);
const char* fivebar_lqr_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_lqr_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_lqr_minmax_closed_loop_sparsity_out(casadi_int i);
int fivebar_lqr_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_lqr_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_lqr_minmax_closed_loop_SZ_ARG 11
#define fivebar_lqr_minmax_closed_loop_SZ_RES 6
#define fivebar_lqr_minmax_closed_loop_SZ_IW 0
#define fivebar_lqr_minmax_closed_loop_SZ_W 109
int fivebar_lqr_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_lqr_preload_closed_loop_checkout(void);
void fivebar_lqr_preload_closed_loop_release(int mem);
void fivebar_lqr_preload_closed_loop_incref(void);
void fivebar_lqr_preload_closed_loop_decref(void);
casadi_int fivebar_lqr_preload_closed_loop_n_in(void);
casadi_int fivebar_lqr_preload_closed_loop_n_out(void);
casadi_real fivebar_lqr_preload_closed_loop_default_in(casadi_int i);
const char* fivebar_lqr_preload_closed_loop_name_in(casadi_int i);
const char* fivebar_lqr_preload_closed_loop_name_out(casadi_int i);
const casadi_int* fivebar_lqr_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fivebar_lqr_preload_closed_loop_sparsity_out(casadi_int i);
int fivebar_lqr_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_lqr_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_lqr_preload_closed_loop_SZ_ARG 16
#define fivebar_lqr_preload_closed_loop_SZ_RES 8
#define fivebar_lqr_preload_closed_loop_SZ_IW 0
#define fivebar_lqr_preload_closed_loop_SZ_W 124
int fivebar_path_coefficients(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_path_coefficients_checkout(void);
void fivebar_path_coefficients_release(int mem);
void fivebar_path_coefficients_incref(void);
void fivebar_path_coefficients_decref(void);
casadi_int fivebar_path_coefficients_n_in(void);
casadi_int fivebar_path_coefficients_n_out(void);
casadi_real fivebar_path_coefficients_default_in(casadi_int i);
const char* fivebar_path_coefficients_name_in(casadi_int i);
const char* fivebar_path_coefficients_name_out(casadi_int i);
const casadi_int* fivebar_path_coefficients_sparsity_in(casadi_int i);
const casadi_int* fivebar_path_coefficients_sparsity_out(casadi_int i);
int fivebar_path_coefficients_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_path_coefficients_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_path_coefficients_SZ_ARG 5
#define fivebar_path_coefficients_SZ_RES 9
#define fivebar_path_coefficients_SZ_IW 0
#define fivebar_path_coefficients_SZ_W 0
int fivebar_path_mvc(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_path_mvc_checkout(void);
void fivebar_path_mvc_release(int mem);
void fivebar_path_mvc_incref(void);
void fivebar_path_mvc_decref(void);
casadi_int fivebar_path_mvc_n_in(void);
casadi_int fivebar_path_mvc_n_out(void);
casadi_real fivebar_path_mvc_default_in(casadi_int i);
const char* fivebar_path_mvc_name_in(casadi_int i);
const char* fivebar_path_mvc_name_out(casadi_int i);
const casadi_int* fivebar_path_mvc_sparsity_in(casadi_int i);
const casadi_int* fivebar_path_mvc_sparsity_out(casadi_int i);
int fivebar_path_mvc_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_path_mvc_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_path_mvc_SZ_ARG 2
#define fivebar_path_mvc_SZ_RES 1
#define fivebar_path_mvc_SZ_IW 0
#define fivebar_path_mvc_SZ_W 0
int fivebar_path_backward(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_path_backward_checkout(void);
void fivebar_path_backward_release(int mem);
void fivebar_path_backward_incref(void);
void fivebar_path_backward_decref(void);
casadi_int fivebar_path_backward_n_in(void);
casadi_int fivebar_path_backward_n_out(void);
casadi_real fivebar_path_backward_default_in(casadi_int i);
const char* fivebar_path_backward_name_in(casadi_int i);
const char* fivebar_path_backward_name_out(casadi_int i);
const casadi_int* fivebar_path_backward_sparsity_in(casadi_int i);
const casadi_int* fivebar_path_backward_sparsity_out(casadi_int i);
int fivebar_path_backward_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_path_backward_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_path_backward_SZ_ARG 22
#define fivebar_path_backward_SZ_RES 9
#define fivebar_path_backward_SZ_IW 0
#define fivebar_path_backward_SZ_W 227
int fivebar_path_forward(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_path_forward_checkout(void);
void fivebar_path_forward_release(int mem);
void fivebar_path_forward_incref(void);
void fivebar_path_forward_decref(void);
casadi_int fivebar_path_forward_n_in(void);
casadi_int fivebar_path_forward_n_out(void);
casadi_real fivebar_path_forward_default_in(casadi_int i);
const char* fivebar_path_forward_name_in(casadi_int i);
const char* fivebar_path_forward_name_out(casadi_int i);
const casadi_int* fivebar_path_forward_sparsity_in(casadi_int i);
const casadi_int* fivebar_path_forward_sparsity_out(casadi_int i);
int fivebar_path_forward_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_path_forward_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_path_forward_SZ_ARG 10
#define fivebar_path_forward_SZ_RES 6
#define fivebar_path_forward_SZ_IW 0
#define fivebar_path_forward_SZ_W 63
int fivebar_path_torques(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_path_torques_checkout(void);
void fivebar_path_torques_release(int mem);
void fivebar_path_torques_incref(void);
void fivebar_path_torques_decref(void);
casadi_int fivebar_path_torques_n_in(void);
casadi_int fivebar_path_torques_n_out(void);
casadi_real fivebar_path_torques_default_in(casadi_int i);
const char* fivebar_path_torques_name_in(casadi_int i);
const char* fivebar_path_torques_name_out(casadi_int i);
const casadi_int* fivebar_path_torques_sparsity_in(casadi_int i);
const casadi_int* fivebar_path_torques_sparsity_out(casadi_int i);
int fivebar_path_torques_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_path_torques_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_path_torques_SZ_ARG 5
#define fivebar_path_torques_SZ_RES 4
#define fivebar_path_torques_SZ_IW 0
#define fivebar_path_torques_SZ_W 0
int fivebar_forward_dynamics_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_forward_dynamics_jacobians_checkout(void);
void fivebar_forward_dynamics_jacobians_release(int mem);
void fivebar_forward_dynamics_jacobians_incref(void);
void fivebar_forward_dynamics_jacobians_decref(void);
casadi_int fivebar_forward_dynamics_jacobians_n_in(void);
casadi_int fivebar_forward_dynamics_jacobians_n_out(void);
casadi_real fivebar_forward_dynamics_jacobians_default_in(casadi_int i);
const char* fivebar_forward_dynamics_jacobians_name_in(casadi_int i);
const char* fivebar_forward_dynamics_jacobians_name_out(casadi_int i);
const casadi_int* fivebar_forward_dynamics_jacobians_sparsity_in(casadi_int i);
const casadi_int* fivebar_forward_dynamics_jacobians_sparsity_out(casadi_int i);
int fivebar_forward_dynamics_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_forward_dynamics_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_forward_dynamics_jacobians_SZ_ARG 4
#define fivebar_forward_dynamics_jacobians_SZ_RES 6
#define fivebar_forward_dynamics_jacobians_SZ_IW 0
#define fivebar_forward_dynamics_jacobians_SZ_W 0
int fivebar_inverse_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_inverse_dynamics_checkout(void);
void fivebar_inverse_dynamics_release(int mem);
void fivebar_inverse_dynamics_incref(void);
void fivebar_inverse_dynamics_decref(void);
casadi_int fivebar_inverse_dynamics_n_in(void);
casadi_int fivebar_inverse_dynamics_n_out(void);
casadi_real fivebar_inverse_dynamics_default_in(casadi_int i);
const char* fivebar_inverse_dynamics_name_in(casadi_int i);
const char* fivebar_inverse_dynamics_name_out(casadi_int i);
const casadi_int* fivebar_inverse_dynamics_sparsity_in(casadi_int i);
const casadi_int* fivebar_inverse_dynamics_sparsity_out(casadi_int i);
int fivebar_inverse_dynamics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_inverse_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_inverse_dynamics_SZ_ARG 4
#define fivebar_inverse_dynamics_SZ_RES 2
#define fivebar_inverse_dynamics_SZ_IW 0
#define fivebar_inverse_dynamics_SZ_W 0
int fivebar_inverse_dynamics_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_inverse_dynamics_jacobians_checkout(void);
void fivebar_inverse_dynamics_jacobians_release(int mem);
void fivebar_inverse_dynamics_jacobians_incref(void);
void fivebar_inverse_dynamics_jacobians_decref(void);
casadi_int fivebar_inverse_dynamics_jacobians_n_in(void);
casadi_int fivebar_inverse_dynamics_jacobians_n_out(void);
casadi_real fivebar_inverse_dynamics_jacobians_default_in(casadi_int i);
const char* fivebar_inverse_dynamics_jacobians_name_in(casadi_int i);
const char* fivebar_inverse_dynamics_jacobians_name_out(casadi_int i);
const casadi_int* fivebar_inverse_dynamics_jacobians_sparsity_in(casadi_int i);
const casadi_int* fivebar_inverse_dynamics_jacobians_sparsity_out(casadi_int i);
int fivebar_inverse_dynamics_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_inverse_dynamics_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_inverse_dynamics_jacobians_SZ_ARG 4
#define fivebar_inverse_dynamics_jacobians_SZ_RES 4
#define fivebar_inverse_dynamics_jacobians_SZ_IW 0
#define fivebar_inverse_dynamics_jacobians_SZ_W 0
int fivebar_sampled_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_sampled_step_checkout(void);
void fivebar_sampled_step_release(int mem);
void fivebar_sampled_step_incref(void);
void fivebar_sampled_step_decref(void);
casadi_int fivebar_sampled_step_n_in(void);
casadi_int fivebar_sampled_step_n_out(void);
casadi_real fivebar_sampled_step_default_in(casadi_int i);
const char* fivebar_sampled_step_name_in(casadi_int i);
const char* fivebar_sampled_step_name_out(casadi_int i);
const casadi_int* fivebar_sampled_step_sparsity_in(casadi_int i);
const casadi_int* fivebar_sampled_step_sparsity_out(casadi_int i);
int fivebar_sampled_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_sampled_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_sampled_step_SZ_ARG 8
#define fivebar_sampled_step_SZ_RES 4
#define fivebar_sampled_step_SZ_IW 0
#define fivebar_sampled_step_SZ_W 72
int fivebar_sampled_step_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_sampled_step_jacobians_checkout(void);
void fivebar_sampled_step_jacobians_release(int mem);
void fivebar_sampled_step_jacobians_incref(void);
void fivebar_sampled_step_jacobians_decref(void);
casadi_int fivebar_sampled_step_jacobians_n_in(void);
casadi_int fivebar_sampled_step_jacobians_n_out(void);
casadi_real fivebar_sampled_step_jacobians_default_in(casadi_int i);
const char* fivebar_sampled_step_jacobians_name_in(casadi_int i);
const char* fivebar_sampled_step_jacobians_name_out(casadi_int i);
const casadi_int* fivebar_sampled_step_jacobians_sparsity_in(casadi_int i);
const casadi_int* fivebar_sampled_step_jacobians_sparsity_out(casadi_int i);
int fivebar_sampled_step_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_sampled_step_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_sampled_step_jacobians_SZ_ARG 8
#define fivebar_sampled_step_jacobians_SZ_RES 10
#define fivebar_sampled_step_jacobians_SZ_IW 7
#define fivebar_sampled_step_jacobians_SZ_W 610
int fivebar_Ge(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_Ge_checkout(void);
void fivebar_Ge_release(int mem);
void fivebar_Ge_incref(void);
void fivebar_Ge_decref(void);
casadi_int fivebar_Ge_n_in(void);
casadi_int fivebar_Ge_n_out(void);
casadi_real fivebar_Ge_default_in(casadi_int i);
const char* fivebar_Ge_name_in(casadi_int i);
const char* fivebar_Ge_name_out(casadi_int i);
const casadi_int* fivebar_Ge_sparsity_in(casadi_int i);
const casadi_int* fivebar_Ge_sparsity_out(casadi_int i);
int fivebar_Ge_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_Ge_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_Ge_SZ_ARG 2
#define fivebar_Ge_SZ_RES 2
#define fivebar_Ge_SZ_IW 0
#define fivebar_Ge_SZ_W 0
int fivebar_kinetic_energy(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_kinetic_energy_checkout(void);
void fivebar_kinetic_energy_release(int mem);
void fivebar_kinetic_energy_incref(void);
void fivebar_kinetic_energy_decref(void);
casadi_int fivebar_kinetic_energy_n_in(void);
casadi_int fivebar_kinetic_energy_n_out(void);
casadi_real fivebar_kinetic_energy_default_in(casadi_int i);
const char* fivebar_kinetic_energy_name_in(casadi_int i);
const char* fivebar_kinetic_energy_name_out(casadi_int i);
const casadi_int* fivebar_kinetic_energy_sparsity_in(casadi_int i);
const casadi_int* fivebar_kinetic_energy_sparsity_out(casadi_int i);
int fivebar_kinetic_energy_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_kinetic_energy_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_kinetic_energy_SZ_ARG 3
#define fivebar_kinetic_energy_SZ_RES 1
#define fivebar_kinetic_energy_SZ_IW 0
#define fivebar_kinetic_energy_SZ_W 0
int fivebar_potential_energy(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fivebar_potential_energy_checkout(void);
void fivebar_potential_energy_release(int mem);
void fivebar_potential_energy_incref(void);
void fivebar_potential_energy_decref(void);
casadi_int fivebar_potential_energy_n_in(void);
casadi_int fivebar_potential_energy_n_out(void);
casadi_real fivebar_potential_energy_default_in(casadi_int i);
const char* fivebar_potential_energy_name_in(casadi_int i);
const char* fivebar_potential_energy_name_out(casadi_int i);
const casadi_int* fivebar_potential_energy_sparsity_in(casadi_int i);
const casadi_int* fivebar_potential_energy_sparsity_out(casadi_int i);
int fivebar_potential_energy_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fivebar_potential_energy_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fivebar_potential_energy_SZ_ARG 2
#define fivebar_potential_energy_SZ_RES 1
#define fivebar_potential_energy_SZ_IW 0
#define fivebar_potential_energy_SZ_W 0
void fivebar_casadi_version(int* major, int* minor, int* patch);
int fivebar_casadi_int_size(void);
int fivebar_casadi_real_size(void);
#ifdef __cplusplus
} /* extern "C" */
#endif

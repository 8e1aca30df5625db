/* pm2dof generated code for model 'fourleg' (4 legs, friction 'coulomb_viscous').
 * Written by `pm2dof derive` from the model file; do not edit.
 *
 * Every function follows CasADi's C API: int f(const double** arg, double** res,
 * long long* iw, double* w, int mem), with work sizes from f_work(). All inputs and
 * outputs are dense; matrices are stored ROW-MAJOR (flattened row by row). SI units.
 *
 * q     = [qa_1..qa_4, qb_1..qb_4]  absolute joint angles, rad (eq. 3 order)
 * qa    = [qa_1..qa_4]  measured active angles, rad
 * xe    = [x, y] end-effector position, m;  xed, xrd, xrdd: velocities m/s, accel. m/s^2
 * theta = [alpha1, alpha2, alpha3, alpha4, beta1, beta2, beta3, beta4, gamma1, gamma2, gamma3, gamma4, fv1, fv2, fv3, fv4, fc1, fc2, fc3, fc4]
 *         (alpha, beta, gamma in kg*m^2; fv in N*m*s/rad; fc, fs in N*m)
 * sing  = [min_i |sin(qb_i - qa_i)| (type I, legs), sqrt(1 - |sum_i exp(2 i qb_i)| / n)
 *         (type II, actuation: sigma_min of S with unit rows over sqrt(n/2))]
 *
 * Functions (inputs -> outputs, element counts):
 *   fourleg_ik(xe[2]) -> (q[8])
 *   fourleg_fk(qa[4]) -> (xe[2], residual[4])
 *   fourleg_H(q[8]) -> (H[6])
 *   fourleg_A(q[8]) -> (A[48])
 *   fourleg_singularity(q[8]) -> (sin_ab[4])
 *   fourleg_singularity_measures(q[8]) -> (sing[2])
 *   fourleg_W(q[8]) -> (W[16], sing[2])
 *   fourleg_S(q[8]) -> (S[8], sing[2])
 *   fourleg_Wdot(q[8], xed[2]) -> (Wdot[16], sing[2])
 *   fourleg_M(q[8], theta[20]) -> (M[64])
 *   fourleg_C(q[8], qd[8], theta[20]) -> (C[64])
 *   fourleg_Me(q[8], theta[20]) -> (Me[4], sing[2])
 *   fourleg_Ce(q[8], xed[2], theta[20]) -> (Ce[4], sing[2])
 *   fourleg_StF(q[8], xed[2], theta[20]) -> (StF[2], sing[2])
 *   fourleg_Y(q[8], xed[2], xrd[2], xrdd[2]) -> (Y[40], sing[2])
 *   fourleg_torque_splits(q[8], u[2], tau_max[4], preload_sign[4], preload[4]) -> (tau_min_norm[4], tau_min_max[4], min_max_ratio[1], tau_preload[4], preload_mode[1], sing[2])
 *   fourleg_forward_dynamics(xe[2], xed[2], tau_a[4], theta[20]) -> (xedd[2], sing[2])
 *   fourleg_na_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[42]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_na_minmax_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[42]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_na_preload_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[42]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_na_proj_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[42]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_na_proj_minmax_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[42]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_na_proj_preload_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[42]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_apd_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[21]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_apd_minmax_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[21]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_apd_preload_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[21]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_ctc_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[21]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_ctc_minmax_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[21]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_ctc_preload_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[21]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_lqr_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[17], K[16], tau_ff[4]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_lqr_minmax_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[17], K[16], tau_ff[4]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_lqr_preload_step(state[24], qa[4], xd[2], xd_dot[2], xd_ddot[2], params[17], K[16], tau_ff[4]) -> (tau_a[4], state_next[24], status[1], diag[10])
 *   fourleg_plant_xedd(xe[2], xed[2], tau_a[4], plant[27]) -> (xedd[2])
 *   fourleg_plant_step(x[4], tau_a[4], plant[27], h[1]) -> (x_next[4])
 *   fourleg_measure(xe[2], plant[27]) -> (qa[4])
 *   fourleg_na_closed_loop(x[28], u[6], p[69]) -> (x_next[28], y[29])
 *   fourleg_na_minmax_closed_loop(x[28], u[6], p[69]) -> (x_next[28], y[29])
 *   fourleg_na_preload_closed_loop(x[28], u[6], p[69]) -> (x_next[28], y[29])
 *   fourleg_na_proj_closed_loop(x[28], u[6], p[69]) -> (x_next[28], y[29])
 *   fourleg_na_proj_minmax_closed_loop(x[28], u[6], p[69]) -> (x_next[28], y[29])
 *   fourleg_na_proj_preload_closed_loop(x[28], u[6], p[69]) -> (x_next[28], y[29])
 *   fourleg_apd_closed_loop(x[28], u[6], p[48]) -> (x_next[28], y[29])
 *   fourleg_apd_minmax_closed_loop(x[28], u[6], p[48]) -> (x_next[28], y[29])
 *   fourleg_apd_preload_closed_loop(x[28], u[6], p[48]) -> (x_next[28], y[29])
 *   fourleg_ctc_closed_loop(x[28], u[6], p[48]) -> (x_next[28], y[29])
 *   fourleg_ctc_minmax_closed_loop(x[28], u[6], p[48]) -> (x_next[28], y[29])
 *   fourleg_ctc_preload_closed_loop(x[28], u[6], p[48]) -> (x_next[28], y[29])
 *   fourleg_lqr_closed_loop(x[28], u[26], p[44]) -> (x_next[28], y[29])
 *   fourleg_lqr_minmax_closed_loop(x[28], u[26], p[44]) -> (x_next[28], y[29])
 *   fourleg_lqr_preload_closed_loop(x[28], u[26], p[44]) -> (x_next[28], y[29])
 *   fourleg_path_coefficients(p[2], dp[2], ddp[2], theta[20], tau_max[4]) -> (a[2], b[2], S[8], v1[4], N_min_norm[8], h_min_norm[4], N_min_max[8], h_min_max[4], sing[2])
 *   fourleg_path_mvc(stage[34], params[21]) -> (x_mvc[1])
 *   fourleg_path_backward(x_next_max[1], input[72], params[21]) -> (x_max[1], y[1])
 *   fourleg_path_forward(x[1], input[73], params[21]) -> (x_next[1], y[6])
 *   fourleg_path_torques(stage[34], sd[1], sdd[1], params[21], tau_max[4]) -> (u[2], tau_min_norm[4], tau_min_max[4], min_max_ratio[1])
 *   fourleg_forward_dynamics_jacobians(xe[2], xed[2], tau_a[4], theta[20]) -> (xedd[2], d_xe[4], d_xed[4], d_tau_a[8], d_theta[40], sing[2])
 *   fourleg_inverse_dynamics(xe[2], xed[2], xedd[2], theta[20]) -> (u[2], sing[2])
 *   fourleg_inverse_dynamics_jacobians(xe[2], xed[2], xedd[2], theta[20]) -> (u[2], d_xe[4], d_xed[4], sing[2])
 *   fourleg_sampled_step(x[4], tau_a[4], theta[20], T[1]) -> (x_next[4], sing[2])
 *   fourleg_sampled_step_jacobians(x[4], tau_a[4], theta[20], T[1]) -> (x_next[4], d_x[16], d_tau_a[16], sing[2])
 *   fourleg_Ge(q[8], theta[20]) -> (Ge[2], sing[2])
 *   fourleg_kinetic_energy(xe[2], xed[2], theta[20]) -> (T[1])
 *   fourleg_potential_energy(xe[2], theta[20]) -> (V[1])
 *
 * Flat vectors of the controllers, plant and closed loop (field[count], in order):
 *   ctrl_state: xe_prev[2], v[2], theta_hat[20]
 *   na_params: Kd[2], Q[2], Gamma[20], freeze_saturated[1], T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[4], preload_sign[4], preload[4], closure_tol[1]
 *   apd_params: Kp[2], Kv[2], T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[4], preload_sign[4], preload[4], closure_tol[1]
 *   ctc_params: Kp[2], Kv[2], T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[4], preload_sign[4], preload[4], closure_tol[1]
 *   lqr_params: T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[4], preload_sign[4], preload[4], closure_tol[1]
 *   cl_state: xe[2], xed[2], ctrl_state[24]
 *   cl_input: xd[2], xd_dot[2], xd_ddot[2]
 *   cl_output: xe[2], xed[2], tau_a[4], status[1], theta_hat[20]
 *   lqr_cl_input: xd[2], xd_dot[2], xd_ddot[2], K[16], tau_ff[4]
 *   plant: alpha[4], beta[4], gamma[4], fv[4], fc[4], fs[4], stribeck_velocity[1], coulomb_smoothing_velocity[1], encoder_step[1]
 *   path_stage: N[8], h[4], a[2], b[2], S[8], v1[4], rho[4], delta[1], x_cap[1]
 *   path_pair: stage[34], next[34], next_cap[1]
 *   path_backward_input: pair[69], same[1], x_in[1], x_out[1]
 *   path_forward_input: pair[69], x_next_max[1], same[1], x_in[1], x_out[1]
 *   path_forward_output: x[1], sdd[1], L[1], U[1], Z[1], arrival_ok[1]
 *   path_params: v_top[1], theta[20]
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

int fourleg_ik(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_ik_checkout(void);
void fourleg_ik_release(int mem);
void fourleg_ik_incref(void);
void fourleg_ik_decref(void);
casadi_int fourleg_ik_n_in(void);
casadi_int fourleg_ik_n_out(void);
casadi_real fourleg_ik_default_in(casadi_int i);
const char* fourleg_ik_name_in(casadi_int i);
const char* fourleg_ik_name_out(casadi_int i);
const casadi_int* fourleg_ik_sparsity_in(casadi_int i);
const casadi_int* fourleg_ik_sparsity_out(casadi_int i);
int fourleg_ik_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_ik_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_ik_SZ_ARG 1
#define fourleg_ik_SZ_RES 1
#define fourleg_ik_SZ_IW 0
#define fourleg_ik_SZ_W 0
int fourleg_fk(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_fk_checkout(void);
void fourleg_fk_release(int mem);
void fourleg_fk_incref(void);
void fourleg_fk_decref(void);
casadi_int fourleg_fk_n_in(void);
casadi_int fourleg_fk_n_out(void);
casadi_real fourleg_fk_default_in(casadi_int i);
const char* fourleg_fk_name_in(casadi_int i);
const char* fourleg_fk_name_out(casadi_int i);
const casadi_int* fourleg_fk_sparsity_in(casadi_int i);
const casadi_int* fourleg_fk_sparsity_out(casadi_int i);
int fourleg_fk_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_fk_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_fk_SZ_ARG 1
#define fourleg_fk_SZ_RES 2
#define fourleg_fk_SZ_IW 0
#define fourleg_fk_SZ_W 0
int fourleg_H(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_H_checkout(void);
void fourleg_H_release(int mem);
void fourleg_H_incref(void);
void fourleg_H_decref(void);
casadi_int fourleg_H_n_in(void);
casadi_int fourleg_H_n_out(void);
casadi_real fourleg_H_default_in(casadi_int i);
const char* fourleg_H_name_in(casadi_int i);
const char* fourleg_H_name_out(casadi_int i);
const casadi_int* fourleg_H_sparsity_in(casadi_int i);
const casadi_int* fourleg_H_sparsity_out(casadi_int i);
int fourleg_H_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_H_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_H_SZ_ARG 1
#define fourleg_H_SZ_RES 1
#define fourleg_H_SZ_IW 0
#define fourleg_H_SZ_W 0
int fourleg_A(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_A_checkout(void);
void fourleg_A_release(int mem);
void fourleg_A_incref(void);
void fourleg_A_decref(void);
casadi_int fourleg_A_n_in(void);
casadi_int fourleg_A_n_out(void);
casadi_real fourleg_A_default_in(casadi_int i);
const char* fourleg_A_name_in(casadi_int i);
const char* fourleg_A_name_out(casadi_int i);
const casadi_int* fourleg_A_sparsity_in(casadi_int i);
const casadi_int* fourleg_A_sparsity_out(casadi_int i);
int fourleg_A_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_A_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_A_SZ_ARG 1
#define fourleg_A_SZ_RES 1
#define fourleg_A_SZ_IW 0
#define fourleg_A_SZ_W 0
int fourleg_singularity(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_singularity_checkout(void);
void fourleg_singularity_release(int mem);
void fourleg_singularity_incref(void);
void fourleg_singularity_decref(void);
casadi_int fourleg_singularity_n_in(void);
casadi_int fourleg_singularity_n_out(void);
casadi_real fourleg_singularity_default_in(casadi_int i);
const char* fourleg_singularity_name_in(casadi_int i);
const char* fourleg_singularity_name_out(casadi_int i);
const casadi_int* fourleg_singularity_sparsity_in(casadi_int i);
const casadi_int* fourleg_singularity_sparsity_out(casadi_int i);
int fourleg_singularity_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_singularity_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_singularity_SZ_ARG 1
#define fourleg_singularity_SZ_RES 1
#define fourleg_singularity_SZ_IW 0
#define fourleg_singularity_SZ_W 0
int fourleg_singularity_measures(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_singularity_measures_checkout(void);
void fourleg_singularity_measures_release(int mem);
void fourleg_singularity_measures_incref(void);
void fourleg_singularity_measures_decref(void);
casadi_int fourleg_singularity_measures_n_in(void);
casadi_int fourleg_singularity_measures_n_out(void);
casadi_real fourleg_singularity_measures_default_in(casadi_int i);
const char* fourleg_singularity_measures_name_in(casadi_int i);
const char* fourleg_singularity_measures_name_out(casadi_int i);
const casadi_int* fourleg_singularity_measures_sparsity_in(casadi_int i);
const casadi_int* fourleg_singularity_measures_sparsity_out(casadi_int i);
int fourleg_singularity_measures_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_singularity_measures_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_singularity_measures_SZ_ARG 1
#define fourleg_singularity_measures_SZ_RES 1
#define fourleg_singularity_measures_SZ_IW 0
#define fourleg_singularity_measures_SZ_W 0
int fourleg_W(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_W_checkout(void);
void fourleg_W_release(int mem);
void fourleg_W_incref(void);
void fourleg_W_decref(void);
casadi_int fourleg_W_n_in(void);
casadi_int fourleg_W_n_out(void);
casadi_real fourleg_W_default_in(casadi_int i);
const char* fourleg_W_name_in(casadi_int i);
const char* fourleg_W_name_out(casadi_int i);
const casadi_int* fourleg_W_sparsity_in(casadi_int i);
const casadi_int* fourleg_W_sparsity_out(casadi_int i);
int fourleg_W_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_W_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_W_SZ_ARG 1
#define fourleg_W_SZ_RES 2
#define fourleg_W_SZ_IW 0
#define fourleg_W_SZ_W 0
int fourleg_S(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_S_checkout(void);
void fourleg_S_release(int mem);
void fourleg_S_incref(void);
void fourleg_S_decref(void);
casadi_int fourleg_S_n_in(void);
casadi_int fourleg_S_n_out(void);
casadi_real fourleg_S_default_in(casadi_int i);
const char* fourleg_S_name_in(casadi_int i);
const char* fourleg_S_name_out(casadi_int i);
const casadi_int* fourleg_S_sparsity_in(casadi_int i);
const casadi_int* fourleg_S_sparsity_out(casadi_int i);
int fourleg_S_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_S_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_S_SZ_ARG 1
#define fourleg_S_SZ_RES 2
#define fourleg_S_SZ_IW 0
#define fourleg_S_SZ_W 0
int fourleg_Wdot(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_Wdot_checkout(void);
void fourleg_Wdot_release(int mem);
void fourleg_Wdot_incref(void);
void fourleg_Wdot_decref(void);
casadi_int fourleg_Wdot_n_in(void);
casadi_int fourleg_Wdot_n_out(void);
casadi_real fourleg_Wdot_default_in(casadi_int i);
const char* fourleg_Wdot_name_in(casadi_int i);
const char* fourleg_Wdot_name_out(casadi_int i);
const casadi_int* fourleg_Wdot_sparsity_in(casadi_int i);
const casadi_int* fourleg_Wdot_sparsity_out(casadi_int i);
int fourleg_Wdot_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_Wdot_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_Wdot_SZ_ARG 2
#define fourleg_Wdot_SZ_RES 2
#define fourleg_Wdot_SZ_IW 0
#define fourleg_Wdot_SZ_W 0
int fourleg_M(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_M_checkout(void);
void fourleg_M_release(int mem);
void fourleg_M_incref(void);
void fourleg_M_decref(void);
casadi_int fourleg_M_n_in(void);
casadi_int fourleg_M_n_out(void);
casadi_real fourleg_M_default_in(casadi_int i);
const char* fourleg_M_name_in(casadi_int i);
const char* fourleg_M_name_out(casadi_int i);
const casadi_int* fourleg_M_sparsity_in(casadi_int i);
const casadi_int* fourleg_M_sparsity_out(casadi_int i);
int fourleg_M_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_M_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_M_SZ_ARG 2
#define fourleg_M_SZ_RES 1
#define fourleg_M_SZ_IW 0
#define fourleg_M_SZ_W 0
int fourleg_C(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_C_checkout(void);
void fourleg_C_release(int mem);
void fourleg_C_incref(void);
void fourleg_C_decref(void);
casadi_int fourleg_C_n_in(void);
casadi_int fourleg_C_n_out(void);
casadi_real fourleg_C_default_in(casadi_int i);
const char* fourleg_C_name_in(casadi_int i);
const char* fourleg_C_name_out(casadi_int i);
const casadi_int* fourleg_C_sparsity_in(casadi_int i);
const casadi_int* fourleg_C_sparsity_out(casadi_int i);
int fourleg_C_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_C_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_C_SZ_ARG 3
#define fourleg_C_SZ_RES 1
#define fourleg_C_SZ_IW 0
#define fourleg_C_SZ_W 0
int fourleg_Me(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_Me_checkout(void);
void fourleg_Me_release(int mem);
void fourleg_Me_incref(void);
void fourleg_Me_decref(void);
casadi_int fourleg_Me_n_in(void);
casadi_int fourleg_Me_n_out(void);
casadi_real fourleg_Me_default_in(casadi_int i);
const char* fourleg_Me_name_in(casadi_int i);
const char* fourleg_Me_name_out(casadi_int i);
const casadi_int* fourleg_Me_sparsity_in(casadi_int i);
const casadi_int* fourleg_Me_sparsity_out(casadi_int i);
int fourleg_Me_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_Me_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_Me_SZ_ARG 2
#define fourleg_Me_SZ_RES 2
#define fourleg_Me_SZ_IW 0
#define fourleg_Me_SZ_W 0
int fourleg_Ce(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_Ce_checkout(void);
void fourleg_Ce_release(int mem);
void fourleg_Ce_incref(void);
void fourleg_Ce_decref(void);
casadi_int fourleg_Ce_n_in(void);
casadi_int fourleg_Ce_n_out(void);
casadi_real fourleg_Ce_default_in(casadi_int i);
const char* fourleg_Ce_name_in(casadi_int i);
const char* fourleg_Ce_name_out(casadi_int i);
const casadi_int* fourleg_Ce_sparsity_in(casadi_int i);
const casadi_int* fourleg_Ce_sparsity_out(casadi_int i);
int fourleg_Ce_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_Ce_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_Ce_SZ_ARG 3
#define fourleg_Ce_SZ_RES 2
#define fourleg_Ce_SZ_IW 0
#define fourleg_Ce_SZ_W 0
int fourleg_StF(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_StF_checkout(void);
void fourleg_StF_release(int mem);
void fourleg_StF_incref(void);
void fourleg_StF_decref(void);
casadi_int fourleg_StF_n_in(void);
casadi_int fourleg_StF_n_out(void);
casadi_real fourleg_StF_default_in(casadi_int i);
const char* fourleg_StF_name_in(casadi_int i);
const char* fourleg_StF_name_out(casadi_int i);
const casadi_int* fourleg_StF_sparsity_in(casadi_int i);
const casadi_int* fourleg_StF_sparsity_out(casadi_int i);
int fourleg_StF_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_StF_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_StF_SZ_ARG 3
#define fourleg_StF_SZ_RES 2
#define fourleg_StF_SZ_IW 0
#define fourleg_StF_SZ_W 0
int fourleg_Y(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_Y_checkout(void);
void fourleg_Y_release(int mem);
void fourleg_Y_incref(void);
void fourleg_Y_decref(void);
casadi_int fourleg_Y_n_in(void);
casadi_int fourleg_Y_n_out(void);
casadi_real fourleg_Y_default_in(casadi_int i);
const char* fourleg_Y_name_in(casadi_int i);
const char* fourleg_Y_name_out(casadi_int i);
const casadi_int* fourleg_Y_sparsity_in(casadi_int i);
const casadi_int* fourleg_Y_sparsity_out(casadi_int i);
int fourleg_Y_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_Y_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_Y_SZ_ARG 4
#define fourleg_Y_SZ_RES 2
#define fourleg_Y_SZ_IW 0
#define fourleg_Y_SZ_W 0
int fourleg_torque_splits(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_torque_splits_checkout(void);
void fourleg_torque_splits_release(int mem);
void fourleg_torque_splits_incref(void);
void fourleg_torque_splits_decref(void);
casadi_int fourleg_torque_splits_n_in(void);
casadi_int fourleg_torque_splits_n_out(void);
casadi_real fourleg_torque_splits_default_in(casadi_int i);
const char* fourleg_torque_splits_name_in(casadi_int i);
const char* fourleg_torque_splits_name_out(casadi_int i);
const casadi_int* fourleg_torque_splits_sparsity_in(casadi_int i);
const casadi_int* fourleg_torque_splits_sparsity_out(casadi_int i);
int fourleg_torque_splits_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_torque_splits_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_torque_splits_SZ_ARG 10
#define fourleg_torque_splits_SZ_RES 8
#define fourleg_torque_splits_SZ_IW 0
#define fourleg_torque_splits_SZ_W 972
int fourleg_forward_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_forward_dynamics_checkout(void);
void fourleg_forward_dynamics_release(int mem);
void fourleg_forward_dynamics_incref(void);
void fourleg_forward_dynamics_decref(void);
casadi_int fourleg_forward_dynamics_n_in(void);
casadi_int fourleg_forward_dynamics_n_out(void);
casadi_real fourleg_forward_dynamics_default_in(casadi_int i);
const char* fourleg_forward_dynamics_name_in(casadi_int i);
const char* fourleg_forward_dynamics_name_out(casadi_int i);
const casadi_int* fourleg_forward_dynamics_sparsity_in(casadi_int i);
const casadi_int* fourleg_forward_dynamics_sparsity_out(casadi_int i);
int fourleg_forward_dynamics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_forward_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_forward_dynamics_SZ_ARG 4
#define fourleg_forward_dynamics_SZ_RES 2
#define fourleg_forward_dynamics_SZ_IW 0
#define fourleg_forward_dynamics_SZ_W 0
int fourleg_na_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_na_step_checkout(void);
void fourleg_na_step_release(int mem);
void fourleg_na_step_incref(void);
void fourleg_na_step_decref(void);
casadi_int fourleg_na_step_n_in(void);
casadi_int fourleg_na_step_n_out(void);
casadi_real fourleg_na_step_default_in(casadi_int i);
const char* fourleg_na_step_name_in(casadi_int i);
const char* fourleg_na_step_name_out(casadi_int i);
const casadi_int* fourleg_na_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_na_step_sparsity_out(casadi_int i);
int fourleg_na_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_na_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_na_step_SZ_ARG 6
#define fourleg_na_step_SZ_RES 4
#define fourleg_na_step_SZ_IW 0
#define fourleg_na_step_SZ_W 0
int fourleg_na_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_na_minmax_step_checkout(void);
void fourleg_na_minmax_step_release(int mem);
void fourleg_na_minmax_step_incref(void);
void fourleg_na_minmax_step_decref(void);
casadi_int fourleg_na_minmax_step_n_in(void);
casadi_int fourleg_na_minmax_step_n_out(void);
casadi_real fourleg_na_minmax_step_default_in(casadi_int i);
const char* fourleg_na_minmax_step_name_in(casadi_int i);
const char* fourleg_na_minmax_step_name_out(casadi_int i);
const casadi_int* fourleg_na_minmax_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_na_minmax_step_sparsity_out(casadi_int i);
int fourleg_na_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_na_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_na_minmax_step_SZ_ARG 6
#define fourleg_na_minmax_step_SZ_RES 4
#define fourleg_na_minmax_step_SZ_IW 0
#define fourleg_na_minmax_step_SZ_W 0
int fourleg_na_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_na_preload_step_checkout(void);
void fourleg_na_preload_step_release(int mem);
void fourleg_na_preload_step_incref(void);
void fourleg_na_preload_step_decref(void);
casadi_int fourleg_na_preload_step_n_in(void);
casadi_int fourleg_na_preload_step_n_out(void);
casadi_real fourleg_na_preload_step_default_in(casadi_int i);
const char* fourleg_na_preload_step_name_in(casadi_int i);
const char* fourleg_na_preload_step_name_out(casadi_int i);
const casadi_int* fourleg_na_preload_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_na_preload_step_sparsity_out(casadi_int i);
int fourleg_na_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_na_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_na_preload_step_SZ_ARG 11
#define fourleg_na_preload_step_SZ_RES 6
#define fourleg_na_preload_step_SZ_IW 0
#define fourleg_na_preload_step_SZ_W 972
int fourleg_na_proj_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_na_proj_step_checkout(void);
void fourleg_na_proj_step_release(int mem);
void fourleg_na_proj_step_incref(void);
void fourleg_na_proj_step_decref(void);
casadi_int fourleg_na_proj_step_n_in(void);
casadi_int fourleg_na_proj_step_n_out(void);
casadi_real fourleg_na_proj_step_default_in(casadi_int i);
const char* fourleg_na_proj_step_name_in(casadi_int i);
const char* fourleg_na_proj_step_name_out(casadi_int i);
const casadi_int* fourleg_na_proj_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_na_proj_step_sparsity_out(casadi_int i);
int fourleg_na_proj_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_na_proj_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_na_proj_step_SZ_ARG 6
#define fourleg_na_proj_step_SZ_RES 4
#define fourleg_na_proj_step_SZ_IW 0
#define fourleg_na_proj_step_SZ_W 0
int fourleg_na_proj_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_na_proj_minmax_step_checkout(void);
void fourleg_na_proj_minmax_step_release(int mem);
void fourleg_na_proj_minmax_step_incref(void);
void fourleg_na_proj_minmax_step_decref(void);
casadi_int fourleg_na_proj_minmax_step_n_in(void);
casadi_int fourleg_na_proj_minmax_step_n_out(void);
casadi_real fourleg_na_proj_minmax_step_default_in(casadi_int i);
const char* fourleg_na_proj_minmax_step_name_in(casadi_int i);
const char* fourleg_na_proj_minmax_step_name_out(casadi_int i);
const casadi_int* fourleg_na_proj_minmax_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_na_proj_minmax_step_sparsity_out(casadi_int i);
int fourleg_na_proj_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_na_proj_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_na_proj_minmax_step_SZ_ARG 6
#define fourleg_na_proj_minmax_step_SZ_RES 4
#define fourleg_na_proj_minmax_step_SZ_IW 0
#define fourleg_na_proj_minmax_step_SZ_W 0
int fourleg_na_proj_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_na_proj_preload_step_checkout(void);
void fourleg_na_proj_preload_step_release(int mem);
void fourleg_na_proj_preload_step_incref(void);
void fourleg_na_proj_preload_step_decref(void);
casadi_int fourleg_na_proj_preload_step_n_in(void);
casadi_int fourleg_na_proj_preload_step_n_out(void);
casadi_real fourleg_na_proj_preload_step_default_in(casadi_int i);
const char* fourleg_na_proj_preload_step_name_in(casadi_int i);
const char* fourleg_na_proj_preload_step_name_out(casadi_int i);
const casadi_int* fourleg_na_proj_preload_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_na_proj_preload_step_sparsity_out(casadi_int i);
int fourleg_na_proj_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_na_proj_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_na_proj_preload_step_SZ_ARG 11
#define fourleg_na_proj_preload_step_SZ_RES 6
#define fourleg_na_proj_preload_step_SZ_IW 0
#define fourleg_na_proj_preload_step_SZ_W 972
int fourleg_apd_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_apd_step_checkout(void);
void fourleg_apd_step_release(int mem);
void fourleg_apd_step_incref(void);
void fourleg_apd_step_decref(void);
casadi_int fourleg_apd_step_n_in(void);
casadi_int fourleg_apd_step_n_out(void);
casadi_real fourleg_apd_step_default_in(casadi_int i);
const char* fourleg_apd_step_name_in(casadi_int i);
const char* fourleg_apd_step_name_out(casadi_int i);
const casadi_int* fourleg_apd_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_apd_step_sparsity_out(casadi_int i);
int fourleg_apd_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_apd_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_apd_step_SZ_ARG 6
#define fourleg_apd_step_SZ_RES 4
#define fourleg_apd_step_SZ_IW 0
#define fourleg_apd_step_SZ_W 0
int fourleg_apd_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_apd_minmax_step_checkout(void);
void fourleg_apd_minmax_step_release(int mem);
void fourleg_apd_minmax_step_incref(void);
void fourleg_apd_minmax_step_decref(void);
casadi_int fourleg_apd_minmax_step_n_in(void);
casadi_int fourleg_apd_minmax_step_n_out(void);
casadi_real fourleg_apd_minmax_step_default_in(casadi_int i);
const char* fourleg_apd_minmax_step_name_in(casadi_int i);
const char* fourleg_apd_minmax_step_name_out(casadi_int i);
const casadi_int* fourleg_apd_minmax_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_apd_minmax_step_sparsity_out(casadi_int i);
int fourleg_apd_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_apd_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_apd_minmax_step_SZ_ARG 6
#define fourleg_apd_minmax_step_SZ_RES 4
#define fourleg_apd_minmax_step_SZ_IW 0
#define fourleg_apd_minmax_step_SZ_W 0
int fourleg_apd_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_apd_preload_step_checkout(void);
void fourleg_apd_preload_step_release(int mem);
void fourleg_apd_preload_step_incref(void);
void fourleg_apd_preload_step_decref(void);
casadi_int fourleg_apd_preload_step_n_in(void);
casadi_int fourleg_apd_preload_step_n_out(void);
casadi_real fourleg_apd_preload_step_default_in(casadi_int i);
const char* fourleg_apd_preload_step_name_in(casadi_int i);
const char* fourleg_apd_preload_step_name_out(casadi_int i);
const casadi_int* fourleg_apd_preload_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_apd_preload_step_sparsity_out(casadi_int i);
int fourleg_apd_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_apd_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_apd_preload_step_SZ_ARG 11
#define fourleg_apd_preload_step_SZ_RES 6
#define fourleg_apd_preload_step_SZ_IW 0
#define fourleg_apd_preload_step_SZ_W 972
int fourleg_ctc_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_ctc_step_checkout(void);
void fourleg_ctc_step_release(int mem);
void fourleg_ctc_step_incref(void);
void fourleg_ctc_step_decref(void);
casadi_int fourleg_ctc_step_n_in(void);
casadi_int fourleg_ctc_step_n_out(void);
casadi_real fourleg_ctc_step_default_in(casadi_int i);
const char* fourleg_ctc_step_name_in(casadi_int i);
const char* fourleg_ctc_step_name_out(casadi_int i);
const casadi_int* fourleg_ctc_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_ctc_step_sparsity_out(casadi_int i);
int fourleg_ctc_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_ctc_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_ctc_step_SZ_ARG 6
#define fourleg_ctc_step_SZ_RES 4
#define fourleg_ctc_step_SZ_IW 0
#define fourleg_ctc_step_SZ_W 0
int fourleg_ctc_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_ctc_minmax_step_checkout(void);
void fourleg_ctc_minmax_step_release(int mem);
void fourleg_ctc_minmax_step_incref(void);
void fourleg_ctc_minmax_step_decref(void);
casadi_int fourleg_ctc_minmax_step_n_in(void);
casadi_int fourleg_ctc_minmax_step_n_out(void);
casadi_real fourleg_ctc_minmax_step_default_in(casadi_int i);
const char* fourleg_ctc_minmax_step_name_in(casadi_int i);
const char* fourleg_ctc_minmax_step_name_out(casadi_int i);
const casadi_int* fourleg_ctc_minmax_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_ctc_minmax_step_sparsity_out(casadi_int i);
int fourleg_ctc_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_ctc_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_ctc_minmax_step_SZ_ARG 6
#define fourleg_ctc_minmax_step_SZ_RES 4
#define fourleg_ctc_minmax_step_SZ_IW 0
#define fourleg_ctc_minmax_step_SZ_W 0
int fourleg_ctc_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_ctc_preload_step_checkout(void);
void fourleg_ctc_preload_step_release(int mem);
void fourleg_ctc_preload_step_incref(void);
void fourleg_ctc_preload_step_decref(void);
casadi_int fourleg_ctc_preload_step_n_in(void);
casadi_int fourleg_ctc_preload_step_n_out(void);
casadi_real fourleg_ctc_preload_step_default_in(casadi_int i);
const char* fourleg_ctc_preload_step_name_in(casadi_int i);
const char* fourleg_ctc_preload_step_name_out(casadi_int i);
const casadi_int* fourleg_ctc_preload_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_ctc_preload_step_sparsity_out(casadi_int i);
int fourleg_ctc_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_ctc_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_ctc_preload_step_SZ_ARG 11
#define fourleg_ctc_preload_step_SZ_RES 6
#define fourleg_ctc_preload_step_SZ_IW 0
#define fourleg_ctc_preload_step_SZ_W 972
int fourleg_lqr_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_lqr_step_checkout(void);
void fourleg_lqr_step_release(int mem);
void fourleg_lqr_step_incref(void);
void fourleg_lqr_step_decref(void);
casadi_int fourleg_lqr_step_n_in(void);
casadi_int fourleg_lqr_step_n_out(void);
casadi_real fourleg_lqr_step_default_in(casadi_int i);
const char* fourleg_lqr_step_name_in(casadi_int i);
const char* fourleg_lqr_step_name_out(casadi_int i);
const casadi_int* fourleg_lqr_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_lqr_step_sparsity_out(casadi_int i);
int fourleg_lqr_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_lqr_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_lqr_step_SZ_ARG 8
#define fourleg_lqr_step_SZ_RES 4
#define fourleg_lqr_step_SZ_IW 0
#define fourleg_lqr_step_SZ_W 0
int fourleg_lqr_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_lqr_minmax_step_checkout(void);
void fourleg_lqr_minmax_step_release(int mem);
void fourleg_lqr_minmax_step_incref(void);
void fourleg_lqr_minmax_step_decref(void);
casadi_int fourleg_lqr_minmax_step_n_in(void);
casadi_int fourleg_lqr_minmax_step_n_out(void);
casadi_real fourleg_lqr_minmax_step_default_in(casadi_int i);
const char* fourleg_lqr_minmax_step_name_in(casadi_int i);
const char* fourleg_lqr_minmax_step_name_out(casadi_int i);
const casadi_int* fourleg_lqr_minmax_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_lqr_minmax_step_sparsity_out(casadi_int i);
int fourleg_lqr_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_lqr_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_lqr_minmax_step_SZ_ARG 8
#define fourleg_lqr_minmax_step_SZ_RES 4
#define fourleg_lqr_minmax_step_SZ_IW 0
#define fourleg_lqr_minmax_step_SZ_W 0
int fourleg_lqr_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_lqr_preload_step_checkout(void);
void fourleg_lqr_preload_step_release(int mem);
void fourleg_lqr_preload_step_incref(void);
void fourleg_lqr_preload_step_decref(void);
casadi_int fourleg_lqr_preload_step_n_in(void);
casadi_int fourleg_lqr_preload_step_n_out(void);
casadi_real fourleg_lqr_preload_step_default_in(casadi_int i);
const char* fourleg_lqr_preload_step_name_in(casadi_int i);
const char* fourleg_lqr_preload_step_name_out(casadi_int i);
const casadi_int* fourleg_lqr_preload_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_lqr_preload_step_sparsity_out(casadi_int i);
int fourleg_lqr_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_lqr_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_lqr_preload_step_SZ_ARG 13
#define fourleg_lqr_preload_step_SZ_RES 6
#define fourleg_lqr_preload_step_SZ_IW 0
#define fourleg_lqr_preload_step_SZ_W 972
int fourleg_plant_xedd(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_plant_xedd_checkout(void);
void fourleg_plant_xedd_release(int mem);
void fourleg_plant_xedd_incref(void);
void fourleg_plant_xedd_decref(void);
casadi_int fourleg_plant_xedd_n_in(void);
casadi_int fourleg_plant_xedd_n_out(void);
casadi_real fourleg_plant_xedd_default_in(casadi_int i);
const char* fourleg_plant_xedd_name_in(casadi_int i);
const char* fourleg_plant_xedd_name_out(casadi_int i);
const casadi_int* fourleg_plant_xedd_sparsity_in(casadi_int i);
const casadi_int* fourleg_plant_xedd_sparsity_out(casadi_int i);
int fourleg_plant_xedd_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_plant_xedd_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_plant_xedd_SZ_ARG 4
#define fourleg_plant_xedd_SZ_RES 1
#define fourleg_plant_xedd_SZ_IW 0
#define fourleg_plant_xedd_SZ_W 0
int fourleg_plant_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_plant_step_checkout(void);
void fourleg_plant_step_release(int mem);
void fourleg_plant_step_incref(void);
void fourleg_plant_step_decref(void);
casadi_int fourleg_plant_step_n_in(void);
casadi_int fourleg_plant_step_n_out(void);
casadi_real fourleg_plant_step_default_in(casadi_int i);
const char* fourleg_plant_step_name_in(casadi_int i);
const char* fourleg_plant_step_name_out(casadi_int i);
const casadi_int* fourleg_plant_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_plant_step_sparsity_out(casadi_int i);
int fourleg_plant_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_plant_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_plant_step_SZ_ARG 4
#define fourleg_plant_step_SZ_RES 1
#define fourleg_plant_step_SZ_IW 0
#define fourleg_plant_step_SZ_W 0
int fourleg_measure(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_measure_checkout(void);
void fourleg_measure_release(int mem);
void fourleg_measure_incref(void);
void fourleg_measure_decref(void);
casadi_int fourleg_measure_n_in(void);
casadi_int fourleg_measure_n_out(void);
casadi_real fourleg_measure_default_in(casadi_int i);
const char* fourleg_measure_name_in(casadi_int i);
const char* fourleg_measure_name_out(casadi_int i);
const casadi_int* fourleg_measure_sparsity_in(casadi_int i);
const casadi_int* fourleg_measure_sparsity_out(casadi_int i);
int fourleg_measure_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_measure_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_measure_SZ_ARG 2
#define fourleg_measure_SZ_RES 1
#define fourleg_measure_SZ_IW 0
#define fourleg_measure_SZ_W 0
int fourleg_na_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_na_closed_loop_checkout(void);
void fourleg_na_closed_loop_release(int mem);
void fourleg_na_closed_loop_incref(void);
void fourleg_na_closed_loop_decref(void);
casadi_int fourleg_na_closed_loop_n_in(void);
casadi_int fourleg_na_closed_loop_n_out(void);
casadi_real fourleg_na_closed_loop_default_in(casadi_int i);
const char* fourleg_na_closed_loop_name_in(casadi_int i);
const char* fourleg_na_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_na_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_na_closed_loop_sparsity_out(casadi_int i);
int fourleg_na_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_na_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_na_closed_loop_SZ_ARG 9
#define fourleg_na_closed_loop_SZ_RES 6
#define fourleg_na_closed_loop_SZ_IW 0
#define fourleg_na_closed_loop_SZ_W 187
int fourleg_na_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_na_minmax_closed_loop_checkout(void);
void fourleg_na_minmax_closed_loop_release(int mem);
void fourleg_na_minmax_closed_loop_incref(void);
void fourleg_na_minmax_closed_loop_decref(void);
casadi_int fourleg_na_minmax_closed_loop_n_in(void);
casadi_int fourleg_na_minmax_closed_loop_n_out(void);
casadi_real fourleg_na_minmax_closed_loop_default_in(casadi_int i);
const char* fourleg_na_minmax_closed_loop_name_in(casadi_int i);
const char* fourleg_na_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_na_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_na_minmax_closed_loop_sparsity_out(casadi_int i);
int fourleg_na_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_na_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_na_minmax_closed_loop_SZ_ARG 9
#define fourleg_na_minmax_closed_loop_SZ_RES 6
#define fourleg_na_minmax_closed_loop_SZ_IW 0
#define fourleg_na_minmax_closed_loop_SZ_W 187
int fourleg_na_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_na_preload_closed_loop_checkout(void);
void fourleg_na_preload_closed_loop_release(int mem);
void fourleg_na_preload_closed_loop_incref(void);
void fourleg_na_preload_closed_loop_decref(void);
casadi_int fourleg_na_preload_closed_loop_n_in(void);
casadi_int fourleg_na_preload_closed_loop_n_out(void);
casadi_real fourleg_na_preload_closed_loop_default_in(casadi_int i);
const char* fourleg_na_preload_closed_loop_name_in(casadi_int i);
const char* fourleg_na_preload_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_na_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_na_preload_closed_loop_sparsity_out(casadi_int i);
int fourleg_na_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_na_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_na_preload_closed_loop_SZ_ARG 14
#define fourleg_na_preload_closed_loop_SZ_RES 8
#define fourleg_na_preload_closed_loop_SZ_IW 0
#define fourleg_na_preload_closed_loop_SZ_W 1145
int fourleg_na_proj_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_na_proj_closed_loop_checkout(void);
void fourleg_na_proj_closed_loop_release(int mem);
void fourleg_na_proj_closed_loop_incref(void);
void fourleg_na_proj_closed_loop_decref(void);
casadi_int fourleg_na_proj_closed_loop_n_in(void);
casadi_int fourleg_na_proj_closed_loop_n_out(void);
casadi_real fourleg_na_proj_closed_loop_default_in(casadi_int i);
const char* fourleg_na_proj_closed_loop_name_in(casadi_int i);
const char* fourleg_na_proj_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_na_proj_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_na_proj_closed_loop_sparsity_out(casadi_int i);
int fourleg_na_proj_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_na_proj_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_na_proj_closed_loop_SZ_ARG 9
#define fourleg_na_proj_closed_loop_SZ_RES 6
#define fourleg_na_proj_closed_loop_SZ_IW 0
#define fourleg_na_proj_closed_loop_SZ_W 187
int fourleg_na_proj_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_na_proj_minmax_closed_loop_checkout(void);
void fourleg_na_proj_minmax_closed_loop_release(int mem);
void fourleg_na_proj_minmax_closed_loop_incref(void);
void fourleg_na_proj_minmax_closed_loop_decref(void);
casadi_int fourleg_na_proj_minmax_closed_loop_n_in(void);
casadi_int fourleg_na_proj_minmax_closed_loop_n_out(void);
casadi_real fourleg_na_proj_minmax_closed_loop_default_in(casadi_int i);
const char* fourleg_na_proj_minmax_closed_loop_name_in(casadi_int i);
const char* fourleg_na_proj_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_na_proj_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_na_proj_minmax_closed_loop_sparsity_out(casadi_int i);
int fourleg_na_proj_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_na_proj_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_na_proj_minmax_closed_loop_SZ_ARG 9
#define fourleg_na_proj_minmax_closed_loop_SZ_RES 6
#define fourleg_na_proj_minmax_closed_loop_SZ_IW 0
#define fourleg_na_proj_minmax_closed_loop_SZ_W 187
int fourleg_na_proj_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_na_proj_preload_closed_loop_checkout(void);
void fourleg_na_proj_preload_closed_loop_release(int mem);
void fourleg_na_proj_preload_closed_loop_incref(void);
void fourleg_na_proj_preload_closed_loop_decref(void);
casadi_int fourleg_na_proj_preload_closed_loop_n_in(void);
casadi_int fourleg_na_proj_preload_closed_loop_n_out(void);
casadi_real fourleg_na_proj_preload_closed_loop_default_in(casadi_int i);
const char* fourleg_na_proj_preload_closed_loop_name_in(casadi_int i);
const char* fourleg_na_proj_preload_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_na_proj_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_na_proj_preload_closed_loop_sparsity_out(casadi_int i);
int fourleg_na_proj_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_na_proj_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_na_proj_preload_closed_loop_SZ_ARG 14
#define fourleg_na_proj_preload_closed_loop_SZ_RES 8
#define fourleg_na_proj_preload_closed_loop_SZ_IW 0
#define fourleg_na_proj_preload_closed_loop_SZ_W 1145
int fourleg_apd_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_apd_closed_loop_checkout(void);
void fourleg_apd_closed_loop_release(int mem);
void fourleg_apd_closed_loop_incref(void);
void fourleg_apd_closed_loop_decref(void);
casadi_int fourleg_apd_closed_loop_n_in(void);
casadi_int fourleg_apd_closed_loop_n_out(void);
casadi_real fourleg_apd_closed_loop_default_in(casadi_int i);
const char* fourleg_apd_closed_loop_name_in(casadi_int i);
const char* fourleg_apd_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_apd_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_apd_closed_loop_sparsity_out(casadi_int i);
int fourleg_apd_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_apd_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_apd_closed_loop_SZ_ARG 9
#define fourleg_apd_closed_loop_SZ_RES 6
#define fourleg_apd_closed_loop_SZ_IW 0
#define fourleg_apd_closed_loop_SZ_W 187
int fourleg_apd_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_apd_minmax_closed_loop_checkout(void);
void fourleg_apd_minmax_closed_loop_release(int mem);
void fourleg_apd_minmax_closed_loop_incref(void);
void fourleg_apd_minmax_closed_loop_decref(void);
casadi_int fourleg_apd_minmax_closed_loop_n_in(void);
casadi_int fourleg_apd_minmax_closed_loop_n_out(void);
casadi_real fourleg_apd_minmax_closed_loop_default_in(casadi_int i);
const char* fourleg_apd_minmax_closed_loop_name_in(casadi_int i);
const char* fourleg_apd_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_apd_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_apd_minmax_closed_loop_sparsity_out(casadi_int i);
int fourleg_apd_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_apd_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_apd_minmax_closed_loop_SZ_ARG 9
#define fourleg_apd_minmax_closed_loop_SZ_RES 6
#define fourleg_apd_minmax_closed_loop_SZ_IW 0
#define fourleg_apd_minmax_closed_loop_SZ_W 187
int fourleg_apd_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_apd_preload_closed_loop_checkout(void);
void fourleg_apd_preload_closed_loop_release(int mem);
void fourleg_apd_preload_closed_loop_incref(void);
void fourleg_apd_preload_closed_loop_decref(void);
casadi_int fourleg_apd_preload_closed_loop_n_in(void);
casadi_int fourleg_apd_preload_closed_loop_n_out(void);
casadi_real fourleg_apd_preload_closed_loop_default_in(casadi_int i);
const char* fourleg_apd_preload_closed_loop_name_in(casadi_int i);
const char* fourleg_apd_preload_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_apd_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_apd_preload_closed_loop_sparsity_out(casadi_int i);
int fourleg_apd_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_apd_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_apd_preload_closed_loop_SZ_ARG 14
#define fourleg_apd_preload_closed_loop_SZ_RES 8
#define fourleg_apd_preload_closed_loop_SZ_IW 0
#define fourleg_apd_preload_closed_loop_SZ_W 1134
int fourleg_ctc_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_ctc_closed_loop_checkout(void);
void fourleg_ctc_closed_loop_release(int mem);
void fourleg_ctc_closed_loop_incref(void);
void fourleg_ctc_closed_loop_decref(void);
casadi_int fourleg_ctc_closed_loop_n_in(void);
casadi_int fourleg_ctc_closed_loop_n_out(void);
casadi_real fourleg_ctc_closed_loop_default_in(casadi_int i);
const char* fourleg_ctc_closed_loop_name_in(casadi_int i);
const char* fourleg_ctc_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_ctc_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_ctc_closed_loop_sparsity_out(casadi_int i);
int fourleg_ctc_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_ctc_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_ctc_closed_loop_SZ_ARG 9
#define fourleg_ctc_closed_loop_SZ_RES 6
#define fourleg_ctc_closed_loop_SZ_IW 0
#define fourleg_ctc_closed_loop_SZ_W 187
int fourleg_ctc_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_ctc_minmax_closed_loop_checkout(void);
void fourleg_ctc_minmax_closed_loop_release(int mem);
void fourleg_ctc_minmax_closed_loop_incref(void);
void fourleg_ctc_minmax_closed_loop_decref(void);
casadi_int fourleg_ctc_minmax_closed_loop_n_in(void);
casadi_int fourleg_ctc_minmax_closed_loop_n_out(void);
casadi_real fourleg_ctc_minmax_closed_loop_default_in(casadi_int i);
const char* fourleg_ctc_minmax_closed_loop_name_in(casadi_int i);
const char* fourleg_ctc_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_ctc_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_ctc_minmax_closed_loop_sparsity_out(casadi_int i);
int fourleg_ctc_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_ctc_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_ctc_minmax_closed_loop_SZ_ARG 9
#define fourleg_ctc_minmax_closed_loop_SZ_RES 6
#define fourleg_ctc_minmax_closed_loop_SZ_IW 0
#define fourleg_ctc_minmax_closed_loop_SZ_W 187
int fourleg_ctc_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_ctc_preload_closed_loop_checkout(void);
void fourleg_ctc_preload_closed_loop_release(int mem);
void fourleg_ctc_preload_closed_loop_incref(void);
void fourleg_ctc_preload_closed_loop_decref(void);
casadi_int fourleg_ctc_preload_closed_loop_n_in(void);
casadi_int fourleg_ctc_preload_closed_loop_n_out(void);
casadi_real fourleg_ctc_preload_closed_loop_default_in(casadi_int i);
const char* fourleg_ctc_preload_closed_loop_name_in(casadi_int i);
const char* fourleg_ctc_preload_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_ctc_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_ctc_preload_closed_loop_sparsity_out(casadi_int i);
int fourleg_ctc_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_ctc_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_ctc_preload_closed_loop_SZ_ARG 14
#define fourleg_ctc_preload_closed_loop_SZ_RES 8
#define fourleg_ctc_preload_closed_loop_SZ_IW 0
#define fourleg_ctc_preload_closed_loop_SZ_W 1128
int fourleg_lqr_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_lqr_closed_loop_checkout(void);
void fourleg_lqr_closed_loop_release(int mem);
void fourleg_lqr_closed_loop_incref(void);
void fourleg_lqr_closed_loop_decref(void);
casadi_int fourleg_lqr_closed_loop_n_in(void);
casadi_int fourleg_lqr_closed_loop_n_out(void);
casadi_real fourleg_lqr_closed_loop_default_in(casadi_int i);
const char* fourleg_lqr_closed_loop_name_in(casadi_int i);
const char* fourleg_lqr_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_lqr_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_lqr_closed_loop_sparsity_out(casadi_int i);
int fourleg_lqr_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_lqr_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_lqr_closed_loop_SZ_ARG 11
#define fourleg_lqr_closed_loop_SZ_RES 6
#define fourleg_lqr_closed_loop_SZ_IW 0
#define fourleg_lqr_closed_loop_SZ_W 175
int fourleg_lqr_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_lqr_minmax_closed_loop_checkout(void);
void fourleg_lqr_minmax_closed_loop_release(int mem);
void fourleg_lqr_minmax_closed_loop_incref(void);
void fourleg_lqr_minmax_closed_loop_decref(void);
casadi_int fourleg_lqr_minmax_closed_loop_n_in(void);
casadi_int fourleg_lqr_minmax_closed_loop_n_out(void);
casadi_real fourleg_lqr_minmax_closed_loop_default_in(casadi_int i);
const char* fourleg_lqr_minmax_closed_loop_name_in(casadi_int i);
const char* fourleg_lqr_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_lqr_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_lqr_minmax_closed_loop_sparsity_out(casadi_int i);
int fourleg_lqr_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_lqr_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_lqr_minmax_closed_loop_SZ_ARG 11
#define fourleg_lqr_minmax_closed_loop_SZ_RES 6
#define fourleg_lqr_minmax_closed_loop_SZ_IW 0
#define fourleg_lqr_minmax_closed_loop_SZ_W 175
int fourleg_lqr_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_lqr_preload_closed_loop_checkout(void);
void fourleg_lqr_preload_closed_loop_release(int mem);
void fourleg_lqr_preload_closed_loop_incref(void);
void fourleg_lqr_preload_closed_loop_decref(void);
casadi_int fourleg_lqr_preload_closed_loop_n_in(void);
casadi_int fourleg_lqr_preload_closed_loop_n_out(void);
casadi_real fourleg_lqr_preload_closed_loop_default_in(casadi_int i);
const char* fourleg_lqr_preload_closed_loop_name_in(casadi_int i);
const char* fourleg_lqr_preload_closed_loop_name_out(casadi_int i);
const casadi_int* fourleg_lqr_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* fourleg_lqr_preload_closed_loop_sparsity_out(casadi_int i);
int fourleg_lqr_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_lqr_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_lqr_preload_closed_loop_SZ_ARG 16
#define fourleg_lqr_preload_closed_loop_SZ_RES 8
#define fourleg_lqr_preload_closed_loop_SZ_IW 0
#define fourleg_lqr_preload_closed_loop_SZ_W 1079
int fourleg_path_coefficients(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_path_coefficients_checkout(void);
void fourleg_path_coefficients_release(int mem);
void fourleg_path_coefficients_incref(void);
void fourleg_path_coefficients_decref(void);
casadi_int fourleg_path_coefficients_n_in(void);
casadi_int fourleg_path_coefficients_n_out(void);
casadi_real fourleg_path_coefficients_default_in(casadi_int i);
const char* fourleg_path_coefficients_name_in(casadi_int i);
const char* fourleg_path_coefficients_name_out(casadi_int i);
const casadi_int* fourleg_path_coefficients_sparsity_in(casadi_int i);
const casadi_int* fourleg_path_coefficients_sparsity_out(casadi_int i);
int fourleg_path_coefficients_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_path_coefficients_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_path_coefficients_SZ_ARG 5
#define fourleg_path_coefficients_SZ_RES 9
#define fourleg_path_coefficients_SZ_IW 0
#define fourleg_path_coefficients_SZ_W 0
int fourleg_path_mvc(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_path_mvc_checkout(void);
void fourleg_path_mvc_release(int mem);
void fourleg_path_mvc_incref(void);
void fourleg_path_mvc_decref(void);
casadi_int fourleg_path_mvc_n_in(void);
casadi_int fourleg_path_mvc_n_out(void);
casadi_real fourleg_path_mvc_default_in(casadi_int i);
const char* fourleg_path_mvc_name_in(casadi_int i);
const char* fourleg_path_mvc_name_out(casadi_int i);
const casadi_int* fourleg_path_mvc_sparsity_in(casadi_int i);
const casadi_int* fourleg_path_mvc_sparsity_out(casadi_int i);
int fourleg_path_mvc_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_path_mvc_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_path_mvc_SZ_ARG 2
#define fourleg_path_mvc_SZ_RES 1
#define fourleg_path_mvc_SZ_IW 0
#define fourleg_path_mvc_SZ_W 0
int fourleg_path_backward(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_path_backward_checkout(void);
void fourleg_path_backward_release(int mem);
void fourleg_path_backward_incref(void);
void fourleg_path_backward_decref(void);
casadi_int fourleg_path_backward_n_in(void);
casadi_int fourleg_path_backward_n_out(void);
casadi_real fourleg_path_backward_default_in(casadi_int i);
const char* fourleg_path_backward_name_in(casadi_int i);
const char* fourleg_path_backward_name_out(casadi_int i);
const casadi_int* fourleg_path_backward_sparsity_in(casadi_int i);
const casadi_int* fourleg_path_backward_sparsity_out(casadi_int i);
int fourleg_path_backward_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_path_backward_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_path_backward_SZ_ARG 22
#define fourleg_path_backward_SZ_RES 9
#define fourleg_path_backward_SZ_IW 0
#define fourleg_path_backward_SZ_W 398
int fourleg_path_forward(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_path_forward_checkout(void);
void fourleg_path_forward_release(int mem);
void fourleg_path_forward_incref(void);
void fourleg_path_forward_decref(void);
casadi_int fourleg_path_forward_n_in(void);
casadi_int fourleg_path_forward_n_out(void);
casadi_real fourleg_path_forward_default_in(casadi_int i);
const char* fourleg_path_forward_name_in(casadi_int i);
const char* fourleg_path_forward_name_out(casadi_int i);
const casadi_int* fourleg_path_forward_sparsity_in(casadi_int i);
const casadi_int* fourleg_path_forward_sparsity_out(casadi_int i);
int fourleg_path_forward_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_path_forward_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_path_forward_SZ_ARG 10
#define fourleg_path_forward_SZ_RES 6
#define fourleg_path_forward_SZ_IW 0
#define fourleg_path_forward_SZ_W 113
int fourleg_path_torques(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_path_torques_checkout(void);
void fourleg_path_torques_release(int mem);
void fourleg_path_torques_incref(void);
void fourleg_path_torques_decref(void);
casadi_int fourleg_path_torques_n_in(void);
casadi_int fourleg_path_torques_n_out(void);
casadi_real fourleg_path_torques_default_in(casadi_int i);
const char* fourleg_path_torques_name_in(casadi_int i);
const char* fourleg_path_torques_name_out(casadi_int i);
const casadi_int* fourleg_path_torques_sparsity_in(casadi_int i);
const casadi_int* fourleg_path_torques_sparsity_out(casadi_int i);
int fourleg_path_torques_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_path_torques_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_path_torques_SZ_ARG 5
#define fourleg_path_torques_SZ_RES 4
#define fourleg_path_torques_SZ_IW 0
#define fourleg_path_torques_SZ_W 0
int fourleg_forward_dynamics_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_forward_dynamics_jacobians_checkout(void);
void fourleg_forward_dynamics_jacobians_release(int mem);
void fourleg_forward_dynamics_jacobians_incref(void);
void fourleg_forward_dynamics_jacobians_decref(void);
casadi_int fourleg_forward_dynamics_jacobians_n_in(void);
casadi_int fourleg_forward_dynamics_jacobians_n_out(void);
casadi_real fourleg_forward_dynamics_jacobians_default_in(casadi_int i);
const char* fourleg_forward_dynamics_jacobians_name_in(casadi_int i);
const char* fourleg_forward_dynamics_jacobians_name_out(casadi_int i);
const casadi_int* fourleg_forward_dynamics_jacobians_sparsity_in(casadi_int i);
const casadi_int* fourleg_forward_dynamics_jacobians_sparsity_out(casadi_int i);
int fourleg_forward_dynamics_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_forward_dynamics_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_forward_dynamics_jacobians_SZ_ARG 4
#define fourleg_forward_dynamics_jacobians_SZ_RES 6
#define fourleg_forward_dynamics_jacobians_SZ_IW 0
#define fourleg_forward_dynamics_jacobians_SZ_W 0
int fourleg_inverse_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_inverse_dynamics_checkout(void);
void fourleg_inverse_dynamics_release(int mem);
void fourleg_inverse_dynamics_incref(void);
void fourleg_inverse_dynamics_decref(void);
casadi_int fourleg_inverse_dynamics_n_in(void);
casadi_int fourleg_inverse_dynamics_n_out(void);
casadi_real fourleg_inverse_dynamics_default_in(casadi_int i);
const char* fourleg_inverse_dynamics_name_in(casadi_int i);
const char* fourleg_inverse_dynamics_name_out(casadi_int i);
const casadi_int* fourleg_inverse_dynamics_sparsity_in(casadi_int i);
const casadi_int* fourleg_inverse_dynamics_sparsity_out(casadi_int i);
int fourleg_inverse_dynamics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_inverse_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_inverse_dynamics_SZ_ARG 4
#define fourleg_inverse_dynamics_SZ_RES 2
#define fourleg_inverse_dynamics_SZ_IW 0
#define fourleg_inverse_dynamics_SZ_W 0
int fourleg_inverse_dynamics_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_inverse_dynamics_jacobians_checkout(void);
void fourleg_inverse_dynamics_jacobians_release(int mem);
void fourleg_inverse_dynamics_jacobians_incref(void);
void fourleg_inverse_dynamics_jacobians_decref(void);
casadi_int fourleg_inverse_dynamics_jacobians_n_in(void);
casadi_int fourleg_inverse_dynamics_jacobians_n_out(void);
casadi_real fourleg_inverse_dynamics_jacobians_default_in(casadi_int i);
const char* fourleg_inverse_dynamics_jacobians_name_in(casadi_int i);
const char* fourleg_inverse_dynamics_jacobians_name_out(casadi_int i);
const casadi_int* fourleg_inverse_dynamics_jacobians_sparsity_in(casadi_int i);
const casadi_int* fourleg_inverse_dynamics_jacobians_sparsity_out(casadi_int i);
int fourleg_inverse_dynamics_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_inverse_dynamics_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_inverse_dynamics_jacobians_SZ_ARG 4
#define fourleg_inverse_dynamics_jacobians_SZ_RES 4
#define fourleg_inverse_dynamics_jacobians_SZ_IW 0
#define fourleg_inverse_dynamics_jacobians_SZ_W 0
int fourleg_sampled_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_sampled_step_checkout(void);
void fourleg_sampled_step_release(int mem);
void fourleg_sampled_step_incref(void);
void fourleg_sampled_step_decref(void);
casadi_int fourleg_sampled_step_n_in(void);
casadi_int fourleg_sampled_step_n_out(void);
casadi_real fourleg_sampled_step_default_in(casadi_int i);
const char* fourleg_sampled_step_name_in(casadi_int i);
const char* fourleg_sampled_step_name_out(casadi_int i);
const casadi_int* fourleg_sampled_step_sparsity_in(casadi_int i);
const casadi_int* fourleg_sampled_step_sparsity_out(casadi_int i);
int fourleg_sampled_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_sampled_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_sampled_step_SZ_ARG 8
#define fourleg_sampled_step_SZ_RES 4
#define fourleg_sampled_step_SZ_IW 0
#define fourleg_sampled_step_SZ_W 110
int fourleg_sampled_step_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_sampled_step_jacobians_checkout(void);
void fourleg_sampled_step_jacobians_release(int mem);
void fourleg_sampled_step_jacobians_incref(void);
void fourleg_sampled_step_jacobians_decref(void);
casadi_int fourleg_sampled_step_jacobians_n_in(void);
casadi_int fourleg_sampled_step_jacobians_n_out(void);
casadi_real fourleg_sampled_step_jacobians_default_in(casadi_int i);
const char* fourleg_sampled_step_jacobians_name_in(casadi_int i);
const char* fourleg_sampled_step_jacobians_name_out(casadi_int i);
const casadi_int* fourleg_sampled_step_jacobians_sparsity_in(casadi_int i);
const casadi_int* fourleg_sampled_step_jacobians_sparsity_out(casadi_int i);
int fourleg_sampled_step_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_sampled_step_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_sampled_step_jacobians_SZ_ARG 8
#define fourleg_sampled_step_jacobians_SZ_RES 10
#define fourleg_sampled_step_jacobians_SZ_IW 9
#define fourleg_sampled_step_jacobians_SZ_W 922
int fourleg_Ge(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_Ge_checkout(void);
void fourleg_Ge_release(int mem);
void fourleg_Ge_incref(void);
void fourleg_Ge_decref(void);
casadi_int fourleg_Ge_n_in(void);
casadi_int fourleg_Ge_n_out(void);
casadi_real fourleg_Ge_default_in(casadi_int i);
const char* fourleg_Ge_name_in(casadi_int i);
const char* fourleg_Ge_name_out(casadi_int i);
const casadi_int* fourleg_Ge_sparsity_in(casadi_int i);
const casadi_int* fourleg_Ge_sparsity_out(casadi_int i);
int fourleg_Ge_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_Ge_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_Ge_SZ_ARG 2
#define fourleg_Ge_SZ_RES 2
#define fourleg_Ge_SZ_IW 0
#define fourleg_Ge_SZ_W 0
int fourleg_kinetic_energy(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_kinetic_energy_checkout(void);
void fourleg_kinetic_energy_release(int mem);
void fourleg_kinetic_energy_incref(void);
void fourleg_kinetic_energy_decref(void);
casadi_int fourleg_kinetic_energy_n_in(void);
casadi_int fourleg_kinetic_energy_n_out(void);
casadi_real fourleg_kinetic_energy_default_in(casadi_int i);
const char* fourleg_kinetic_energy_name_in(casadi_int i);
const char* fourleg_kinetic_energy_name_out(casadi_int i);
const casadi_int* fourleg_kinetic_energy_sparsity_in(casadi_int i);
const casadi_int* fourleg_kinetic_energy_sparsity_out(casadi_int i);
int fourleg_kinetic_energy_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_kinetic_energy_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_kinetic_energy_SZ_ARG 3
#define fourleg_kinetic_energy_SZ_RES 1
#define fourleg_kinetic_energy_SZ_IW 0
#define fourleg_kinetic_energy_SZ_W 0
int fourleg_potential_energy(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int fourleg_potential_energy_checkout(void);
void fourleg_potential_energy_release(int mem);
void fourleg_potential_energy_incref(void);
void fourleg_potential_energy_decref(void);
casadi_int fourleg_potential_energy_n_in(void);
casadi_int fourleg_potential_energy_n_out(void);
casadi_real fourleg_potential_energy_default_in(casadi_int i);
const char* fourleg_potential_energy_name_in(casadi_int i);
const char* fourleg_potential_energy_name_out(casadi_int i);
const casadi_int* fourleg_potential_energy_sparsity_in(casadi_int i);
const casadi_int* fourleg_potential_energy_sparsity_out(casadi_int i);
int fourleg_potential_energy_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int fourleg_potential_energy_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define fourleg_potential_energy_SZ_ARG 2
#define fourleg_potential_energy_SZ_RES 1
#define fourleg_potential_energy_SZ_IW 0
#define fourleg_potential_energy_SZ_W 0
void fourleg_casadi_version(int* major, int* minor, int* patch);
int fourleg_casadi_int_size(void);
int fourleg_casadi_real_size(void);
#ifdef __cplusplus
} /* extern "C" */
#endif

"""
The excavator dipper-joint plant (docs/explanation/plant.md) integrated by SUNDIALS CVODE: parameters,
command signals (submodule ``excitation``), ``simulate`` and ``SteppingPlant`` (one sample per
call); the paper's experiment on it is ``bonl.experiment``.
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
from . import excitation
__all__: tuple = ('Parameters', 'Command', 'excitation', 'simulate', 'Trajectory', 'initial_state', 'derivative', 'SteppingPlant', 'Measurement')
class Parameters:
    """
    Parameters of the excavator dipper-joint plant (docs/explanation/plant.md).
    
    Valve, asymmetric cylinder, linkage and backlash of a 20 t excavator's stick cylinder by
    default (``Parameters.excavator_20t()``); ``Parameters.excavator_5t()`` gives the 5-6 t machine.
    Every value can be overridden, as a keyword argument of the constructor or by assigning the
    attribute; ``validate()`` rejects non-physical values with a ValueError that names the parameter
    (``simulate`` validates too).
    
    Parameters
    ----------
    **overrides : float
        Any of the attributes below, e.g. ``Parameters(pilot_hysteresis=0.0)``.
    
    Attributes
    ----------
    bore_diameter : float
        D, cylinder bore diameter [m].
    rod_diameter : float
        d, piston rod diameter [m].
    stroke : float
        L, cylinder stroke [m].
    dead_volume_head : float
        V01, head-side dead plus hose volume [m^3].
    dead_volume_rod : float
        V02, rod-side dead plus hose volume [m^3].
    supply_pressure : float
        ps, supply pressure [Pa].
    return_pressure : float
        pt, return (tank) pressure [Pa].
    bulk_modulus : float
        beta_e, effective bulk modulus of the oil [Pa].
    oil_density : float
        rho, oil density [kg/m^3].
    discharge_coefficient : float
        Cd, orifice discharge coefficient [-].
    area_gradient : float
        w, orifice area gradient of the spool [m].
    spool_travel : float
        xv_max, spool travel at full opening [m].
    internal_leakage : float
        Ci, internal (cross-piston) leakage coefficient [m^3/(s Pa)].
    external_leakage : float
        Ce, external leakage coefficient [m^3/(s Pa)].
    orifice_smoothing : float
        dp_reg, orifice square-root smoothing pressure [Pa].
    valve_time_constant : float
        tau_v, valve (spool) time constant [s].
    dead_band : float
        d, input dead-band half-width [V].
    neutral_voltage : float
        V0, neutral command voltage [V].
    max_voltage : float
        Upper end of the command range; V saturates to [0, max_voltage] [V].
    pilot_hysteresis : float
        hv, pilot-stage hysteresis half-width as a fraction of full opening [-] (the valve backlash).
    mass : float
        M, equivalent moving mass at the rod [kg].
    gravity_moment : float
        m_dcg, gravity first moment of stick plus bucket [kg m].
    gravity_angle_offset : float
        theta_g, gravity angle offset [rad].
    gravity : float
        g, gravitational acceleration [m/s^2].
    coulomb_friction : float
        Fc, Coulomb friction force [N].
    static_friction : float
        Fst, static (breakaway) friction force [N].
    stribeck_velocity : float
        vs, Stribeck velocity [m/s].
    viscous_friction : float
        sigma_v, viscous friction coefficient [N s/m].
    friction_smoothing : float
        eps_v, friction sign smoothing velocity [m/s].
    end_stop_stiffness : float
        k_end, end-stop stiffness [N/m].
    end_stop_damping : float
        c_end, end-stop damping [N s/m].
    pivot_to_rod_pin : float
        a, distance from the joint pivot to the rod pin [m].
    pivot_to_base_pin : float
        b, distance from the joint pivot to the cylinder base pin [m].
    retracted_length : float
        l_min, pin-to-pin cylinder length at h = 0 [m].
    joint_backlash : float
        delta, total backlash in the pins [rad].
    sensor_noise : float
        sigma_theta, inclinometer noise standard deviation [rad].
    """
    __hash__: typing.ClassVar[None] = None
    @staticmethod
    def excavator_20t() -> Parameters:
        """
        The 20 t excavator's stick cylinder (plant.md's defaults, as ``Parameters()``).
        
        Returns
        -------
        Parameters
        """
    @staticmethod
    def excavator_5t() -> Parameters:
        """
        The 5-6 t machine of plant.md.
        
        Returns
        -------
        Parameters
        """
    def __copy__(self) -> Parameters:
        ...
    def __deepcopy__(self, memo: dict) -> Parameters:
        ...
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Default (20 t) parameters, with any attribute overridden by keyword.
        
        Raises
        ------
        TypeError
            For a keyword that is not a parameter's name.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def angle_offset(self) -> float:
        """
        phi0, the linkage angle at mid-stroke.
        
        Returns
        -------
        float
            phi0 [rad].
        """
    def annulus_area(self) -> float:
        """
        The annulus area A2 = pi (D^2 - d^2) / 4.
        
        Returns
        -------
        float
            A2 [m^2].
        """
    def copy(self) -> Parameters:
        """
        An independent copy.
        
        Returns
        -------
        Parameters
            The copy, equal to this one.
        """
    def flow_gain(self) -> float:
        """
        The flow gain Kq = Cd w xv_max sqrt(2 / rho).
        
        Returns
        -------
        float
            Kq [m^3/(s sqrt(Pa))].
        """
    def gravity_force(self, position: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        Spring (gravity) force at the rod, Fs(h) = m_dcg g cos(theta + theta_g) / r(h).
        
        Parameters
        ----------
        position : float
            h [m].
        
        Returns
        -------
        float
            Fs [N].
        """
    def head_area(self) -> float:
        """
        The piston area A1 = pi D^2 / 4.
        
        Returns
        -------
        float
            A1 [m^2].
        """
    def joint_angle(self, position: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        Joint angle theta = phi(h) - phi0.
        
        Parameters
        ----------
        position : float
            h [m].
        
        Returns
        -------
        float
            theta [rad].
        """
    def linkage_angle(self, position: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        Linkage angle phi at piston position h (law of cosines).
        
        Parameters
        ----------
        position : float
            h [m].
        
        Returns
        -------
        float
            phi [rad].
        """
    def moment_arm(self, position: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        Moment arm r(h) = a b sin(phi) / l, so that dtheta/dt = v / r.
        
        Parameters
        ----------
        position : float
            h [m].
        
        Returns
        -------
        float
            r [m].
        """
    def to_dict(self) -> dict:
        """
        Every parameter by name.
        
        Returns
        -------
        dict[str, float]
        """
    def validate(self) -> None:
        """
        Check that every parameter is physical.
        
        Raises
        ------
        ValueError
            Naming the first non-physical parameter, its requirement and its value.
        """
    def valve_gain(self) -> float:
        """
        The valve gain kv = 1 / (V0 - d): a full command opens the spool fully.
        
        Returns
        -------
        float
            kv [1/V].
        """
    @property
    def area_gradient(self) -> float:
        """
        w, orifice area gradient of the spool [m].
        """
    @area_gradient.setter
    def area_gradient(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def bore_diameter(self) -> float:
        """
        D, cylinder bore diameter [m].
        """
    @bore_diameter.setter
    def bore_diameter(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def bulk_modulus(self) -> float:
        """
        beta_e, effective bulk modulus of the oil [Pa].
        """
    @bulk_modulus.setter
    def bulk_modulus(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def coulomb_friction(self) -> float:
        """
        Fc, Coulomb friction force [N].
        """
    @coulomb_friction.setter
    def coulomb_friction(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def dead_band(self) -> float:
        """
        d, input dead-band half-width [V].
        """
    @dead_band.setter
    def dead_band(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def dead_volume_head(self) -> float:
        """
        V01, head-side dead plus hose volume [m^3].
        """
    @dead_volume_head.setter
    def dead_volume_head(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def dead_volume_rod(self) -> float:
        """
        V02, rod-side dead plus hose volume [m^3].
        """
    @dead_volume_rod.setter
    def dead_volume_rod(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def discharge_coefficient(self) -> float:
        """
        Cd, orifice discharge coefficient [-].
        """
    @discharge_coefficient.setter
    def discharge_coefficient(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def end_stop_damping(self) -> float:
        """
        c_end, end-stop damping [N s/m].
        """
    @end_stop_damping.setter
    def end_stop_damping(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def end_stop_stiffness(self) -> float:
        """
        k_end, end-stop stiffness [N/m].
        """
    @end_stop_stiffness.setter
    def end_stop_stiffness(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def external_leakage(self) -> float:
        """
        Ce, external leakage coefficient [m^3/(s Pa)].
        """
    @external_leakage.setter
    def external_leakage(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def friction_smoothing(self) -> float:
        """
        eps_v, friction sign smoothing velocity [m/s].
        """
    @friction_smoothing.setter
    def friction_smoothing(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def gravity(self) -> float:
        """
        g, gravitational acceleration [m/s^2].
        """
    @gravity.setter
    def gravity(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def gravity_angle_offset(self) -> float:
        """
        theta_g, gravity angle offset [rad].
        """
    @gravity_angle_offset.setter
    def gravity_angle_offset(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def gravity_moment(self) -> float:
        """
        m_dcg, gravity first moment of stick plus bucket [kg m].
        """
    @gravity_moment.setter
    def gravity_moment(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def internal_leakage(self) -> float:
        """
        Ci, internal (cross-piston) leakage coefficient [m^3/(s Pa)].
        """
    @internal_leakage.setter
    def internal_leakage(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def joint_backlash(self) -> float:
        """
        delta, total backlash in the pins [rad].
        """
    @joint_backlash.setter
    def joint_backlash(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def mass(self) -> float:
        """
        M, equivalent moving mass at the rod [kg].
        """
    @mass.setter
    def mass(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def max_voltage(self) -> float:
        """
        Upper end of the command range; V saturates to [0, max_voltage] [V].
        """
    @max_voltage.setter
    def max_voltage(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def neutral_voltage(self) -> float:
        """
        V0, neutral command voltage [V].
        """
    @neutral_voltage.setter
    def neutral_voltage(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def oil_density(self) -> float:
        """
        rho, oil density [kg/m^3].
        """
    @oil_density.setter
    def oil_density(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def orifice_smoothing(self) -> float:
        """
        dp_reg, orifice square-root smoothing pressure [Pa].
        """
    @orifice_smoothing.setter
    def orifice_smoothing(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def pilot_hysteresis(self) -> float:
        """
        hv, pilot-stage hysteresis half-width as a fraction of full opening [-] (the valve backlash).
        """
    @pilot_hysteresis.setter
    def pilot_hysteresis(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def pivot_to_base_pin(self) -> float:
        """
        b, distance from the joint pivot to the cylinder base pin [m].
        """
    @pivot_to_base_pin.setter
    def pivot_to_base_pin(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def pivot_to_rod_pin(self) -> float:
        """
        a, distance from the joint pivot to the rod pin [m].
        """
    @pivot_to_rod_pin.setter
    def pivot_to_rod_pin(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def retracted_length(self) -> float:
        """
        l_min, pin-to-pin cylinder length at h = 0 [m].
        """
    @retracted_length.setter
    def retracted_length(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def return_pressure(self) -> float:
        """
        pt, return (tank) pressure [Pa].
        """
    @return_pressure.setter
    def return_pressure(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def rod_diameter(self) -> float:
        """
        d, piston rod diameter [m].
        """
    @rod_diameter.setter
    def rod_diameter(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def sensor_noise(self) -> float:
        """
        sigma_theta, inclinometer noise standard deviation [rad].
        """
    @sensor_noise.setter
    def sensor_noise(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def spool_travel(self) -> float:
        """
        xv_max, spool travel at full opening [m].
        """
    @spool_travel.setter
    def spool_travel(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def static_friction(self) -> float:
        """
        Fst, static (breakaway) friction force [N].
        """
    @static_friction.setter
    def static_friction(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def stribeck_velocity(self) -> float:
        """
        vs, Stribeck velocity [m/s].
        """
    @stribeck_velocity.setter
    def stribeck_velocity(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def stroke(self) -> float:
        """
        L, cylinder stroke [m].
        """
    @stroke.setter
    def stroke(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def supply_pressure(self) -> float:
        """
        ps, supply pressure [Pa].
        """
    @supply_pressure.setter
    def supply_pressure(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def valve_time_constant(self) -> float:
        """
        tau_v, valve (spool) time constant [s].
        """
    @valve_time_constant.setter
    def valve_time_constant(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def viscous_friction(self) -> float:
        """
        sigma_v, viscous friction coefficient [N s/m].
        """
    @viscous_friction.setter
    def viscous_friction(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class Command:
    """
    A command voltage V(t) [V] on the 0-5 V scale (neutral 2.5 V).
    
    Made by the functions of ``bonl.plant.excitation`` (evaluated in C++, so ``simulate``
    releases the GIL), or from any Python callable ``f(t) -> float``.
    
    Parameters
    ----------
    function : callable
        f(t) -> float, t in seconds, V in volts.
    """
    def __call__(self, t: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        V(t).
        
        Parameters
        ----------
        t : float
            Time [s].
        
        Returns
        -------
        float
            Command [V].
        """
    def __init__(self, function: collections.abc.Callable) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def sample(self, t: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        V at every time of an array.
        
        Parameters
        ----------
        t : array_like, 1-D
            Finite times [s].
        
        Returns
        -------
        numpy.ndarray
            float64 commands [V], the same length as ``t``.
        
        Raises
        ------
        ValueError
            When ``t`` is not 1-D or not finite.
        """
    @property
    def calls_python(self) -> bool:
        """
        True when the command wraps a Python callable (``simulate`` then keeps the GIL).
        """
class Trajectory:
    """
    What ``simulate`` returns: float64 arrays on the output grid, sample k at ``time[k] = k * sample_time``,
    and the run's summary (``min_position``, ``max_position``, ``reached_end_stop``, ``steps``).
    """
    def __len__(self) -> int:
        ...
    def __repr__(self) -> str:
        ...
    def to_dict(self) -> dict[str, numpy.typing.NDArray[numpy.float64] | float | bool | int]:
        """
        Every field by name (the arrays view this Trajectory's).
        
        Returns
        -------
        dict[str, numpy.ndarray | float | bool | int]
        """
    @property
    def command(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: V, as held on the command grid [V].
        """
    @property
    def head_flow(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: Q1, into the head chamber [m^3/s].
        """
    @property
    def head_pressure(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: p1 [Pa].
        """
    @property
    def input(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: u = V - V0, the identification input [V].
        """
    @property
    def joint_angle(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: theta [rad].
        """
    @property
    def joint_rate(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: dtheta/dt = v / r(h) [rad/s].
        """
    @property
    def max_position(self) -> float:
        """
        float: largest h reached on the command grid [m].
        """
    @property
    def measured_angle(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: theta_m + sensor noise [rad].
        """
    @property
    def min_position(self) -> float:
        """
        float: smallest h reached on the command grid [m].
        """
    @property
    def pilot(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: xc, the pilot stage's output (after its hysteresis) [-].
        """
    @property
    def pin_angle(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: theta_m = play(theta; delta / 2), noise-free [rad].
        """
    @property
    def position(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: h [m].
        """
    @property
    def reached_end_stop(self) -> bool:
        """
        bool: h left [0, L] at some point of the command grid.
        """
    @property
    def rod_flow(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: Q2, out of the rod chamber [m^3/s].
        """
    @property
    def rod_pressure(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: p2 [Pa].
        """
    @property
    def spool(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: xv [-].
        """
    @property
    def steps(self) -> int:
        """
        int: CVODE's internal steps.
        """
    @property
    def time(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: t_k = k * sample_time [s].
        """
    @property
    def velocity(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        numpy.ndarray: v [m/s].
        """
class Measurement:
    """
    The plant at one sample time t_k, as ``SteppingPlant.step`` returns it: the
    measured angle, and the true states for analysis (simulate's sample k).
    """
    def __repr__(self) -> str:
        ...
    def to_dict(self) -> dict:
        """
        Every field by name.
        
        Returns
        -------
        dict[str, float | bool]
        """
    @property
    def head_flow(self) -> float:
        """
        float: Q1, into the head chamber [m^3/s].
        """
    @property
    def head_pressure(self) -> float:
        """
        float: p1 [Pa].
        """
    @property
    def joint_angle(self) -> float:
        """
        float: theta [rad].
        """
    @property
    def joint_rate(self) -> float:
        """
        float: dtheta/dt = v / r(h) [rad/s].
        """
    @property
    def measured_angle(self) -> float:
        """
        float: pin_angle plus the sensor noise: what the inclinometer reads [rad].
        """
    @property
    def pilot(self) -> float:
        """
        float: xc, the pilot stage's output held over the last command interval before t_k (0 before the
        first step) [-]: simulate's ``pilot[k - 1]`` under a command held over each sample.
        """
    @property
    def pin_angle(self) -> float:
        """
        float: theta_m = play(theta; delta / 2), noise-free [rad].
        """
    @property
    def position(self) -> float:
        """
        float: h, the piston position [m].
        """
    @property
    def reached_end_stop(self) -> bool:
        """
        bool: h left [0, L] at a command-grid point of the step that ended at t_k.
        """
    @property
    def rod_flow(self) -> float:
        """
        float: Q2, out of the rod chamber [m^3/s].
        """
    @property
    def rod_pressure(self) -> float:
        """
        float: p2 [Pa].
        """
    @property
    def spool(self) -> float:
        """
        float: xv, the spool opening [-].
        """
    @property
    def time(self) -> float:
        """
        float: t_k [s].
        """
    @property
    def velocity(self) -> float:
        """
        float: v [m/s].
        """
class SteppingPlant:
    """
    The plant advanced one sample per call: ``measurement = plant.step(command)``.
    
    From rest at t = 0, ``step(V)`` holds the command V [V] over one sample (``sample_time``, on the
    ``command_rate`` grid), integrates with CVODE and returns the ``Measurement`` at the sample's end:
    the commands V_0, V_1, ... give the measurements at t_1, t_2, ...; the one at t_0 is ``measurement``
    after construction or ``reset()``. ``simulate`` under the same commands held over each sample
    (``(values, sample_time)``) gives the same samples, sensor noise included: its sample k pairs the
    state at t_k with the command V_k that follows it. simulate is a loop over the same integration.
    
    Parameters
    ----------
    parameters : Parameters, optional
        The plant; None: ``Parameters.excavator_20t()``.
    sample_time, command_rate, rtol, atol, max_steps_per_interval, sensor_noise, noise_seed, initial_position, load
        As for ``simulate`` (which has ``duration`` too: a stepping plant runs as long as it is stepped),
        validated the same way.
    
    Raises
    ------
    ValueError
        For non-physical parameters or bad options, naming them.
    
    Examples
    --------
    >>> from bonl import plant
    >>> p = plant.SteppingPlant()
    >>> start = p.measurement                  # at t = 0, from rest at mid-stroke
    >>> m = p.step(3.0)                        # 3 V held for 0.01 s
    >>> m.time, m.measured_angle               # doctest: +SKIP
    (0.01, ...)
    """
    def __init__(self, parameters: Parameters | None = None, *, sample_time: typing.SupportsFloat | typing.SupportsIndex = 0.01, command_rate: typing.SupportsFloat | typing.SupportsIndex = 1000.0, rtol: typing.SupportsFloat | typing.SupportsIndex = 1e-06, atol: dict[str, float] | None = None, max_steps_per_interval: typing.SupportsInt | typing.SupportsIndex = 5000, sensor_noise: bool = True, noise_seed: typing.SupportsInt | typing.SupportsIndex = 1, initial_position: float | None = None, load: Command | collections.abc.Callable[[float], float] | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def reset(self, initial_position: float | None = None, noise_seed: typing.SupportsInt | typing.SupportsIndex | None = None) -> Measurement:
        """
        Back to rest at t = 0.
        
        Parameters
        ----------
        initial_position : float, optional
            h0 [m]; None: the plant's (the constructor's or the last reset's).
        noise_seed : int, optional
            The sensor noise's seed; None: the plant's. The same seed and commands give the same measurements.
        
        Returns
        -------
        Measurement
            At t = 0.
        
        Raises
        ------
        ValueError
            For a bad ``initial_position``; the plant is left as it was.
        """
    def set_parameters(self, parameters: Parameters | None) -> None:
        """
        Change the plant from the current sample on, keeping its state.
        
        As a machine changes in service (the oil warms and its bulk modulus drops, the pilot valve wears):
        the next ``step`` runs with ``parameters`` from the state the plant is in (position, velocity,
        pressures, spool, the hysteresis' and the backlash's memories, the noise sequence). Later ``reset()``\\s
        keep the new parameters.
        
        Parameters
        ----------
        parameters : Parameters
            The new parameters. The linkage's geometry (``stroke``, ``pivot_to_rod_pin``,
            ``pivot_to_base_pin``, ``retracted_length``) must stay as it is.
        
        Raises
        ------
        ValueError
            For non-physical parameters or a changed geometry, naming them; the plant is left as it was.
        """
    def step(self, command: float) -> Measurement:
        """
        Hold ``command`` over one sample and return the measurement at its end.
        
        Parameters
        ----------
        command : float
            V [V] on the 0-5 V scale (neutral 2.5 V).
        
        Returns
        -------
        Measurement
            At ``time + sample_time``.
        
        Raises
        ------
        ValueError
            For a command that is not a finite real number, or a load that is not finite within the step;
            the plant is left as it was.
        bonl.NumericalError
            When CVODE fails; the plant is then left failed (``RuntimeError`` until ``reset()``).
        """
    @property
    def measurement(self) -> Measurement:
        """
        Measurement: the latest, at ``time`` (a copy).
        """
    @property
    def parameters(self) -> Parameters:
        """
        Parameters: a copy of the plant's parameters.
        """
    @property
    def sample_time(self) -> float:
        """
        float: the time one step advances [s].
        """
    @property
    def steps(self) -> int:
        """
        int: CVODE's internal steps since the start or reset.
        """
    @property
    def time(self) -> float:
        """
        float: t_k, the latest measurement's time [s].
        """
def derivative(parameters: Parameters | None, state: numpy.typing.ArrayLike, pilot: typing.SupportsFloat | typing.SupportsIndex, load: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> numpy.typing.NDArray[numpy.float64]:
    """
    Right-hand side of the plant's ODE, d(state)/dt, for a held pilot output and load.
    
    Exposed so that tests can check the plant against an independent integrator.
    
    Parameters
    ----------
    parameters : Parameters or None
        The plant.
    state : array_like of 5
        (h [m], v [m/s], p1 [Pa], p2 [Pa], xv [-]).
    pilot : float
        xc, the pilot stage's output after its hysteresis [-].
    load : float, optional
        F_L [N].
    
    Returns
    -------
    numpy.ndarray
        d(state)/dt, 5 entries.
    """
def initial_state(parameters: Parameters | None, position: typing.SupportsFloat | typing.SupportsIndex) -> numpy.typing.NDArray[numpy.float64]:
    """
    Initial state of plant.md's experiment at piston position h0.
    
    At rest, spool closed, p2 = ps / 4, p1 from the force balance A1 p1 = A2 p2 + Fs(h0).
    
    Parameters
    ----------
    parameters : Parameters or None
        The plant.
    position : float
        h0 [m].
    
    Returns
    -------
    numpy.ndarray
        The state (h [m], v [m/s], p1 [Pa], p2 [Pa], xv [-]).
    """
def simulate(command: Command | collections.abc.Callable[[float], float] | tuple[numpy.typing.ArrayLike, float], parameters: Parameters | None = None, *, duration: typing.SupportsFloat | typing.SupportsIndex = 50.0, sample_time: typing.SupportsFloat | typing.SupportsIndex = 0.01, command_rate: typing.SupportsFloat | typing.SupportsIndex = 1000.0, rtol: typing.SupportsFloat | typing.SupportsIndex = 1e-06, atol: dict[str, float] | None = None, max_steps_per_interval: typing.SupportsInt | typing.SupportsIndex = 5000, sensor_noise: bool = True, noise_seed: typing.SupportsInt | typing.SupportsIndex = 1, initial_position: float | None = None, load: Command | collections.abc.Callable[[float], float] | None = None) -> Trajectory:
    """
    Integrate the plant under a command with CVODE (BDF, Newton, dense solver).
    
    The command is sampled and held on the command grid (``command_rate``), where the pilot
    hysteresis and the pin backlash (play operators) are evaluated; CVODE stops at every output
    sample, so sample k depends only on the commands before ``time[k]`` (``SteppingPlant`` steps
    the same integration). The GIL is released unless the command or the load is a Python callable.
    
    Parameters
    ----------
    command : Command or callable or tuple
        V(t) [V]: a ``Command`` (``bonl.plant.excitation``), a Python callable f(t) -> float, or a
        ``(values, ts)`` pair held between samples (``excitation.sampled``).
    parameters : Parameters, optional
        The plant; None: ``Parameters.excavator_20t()``.
    duration : float, optional
        [s], an integer multiple of ``sample_time``.
    sample_time : float, optional
        Output grid [s], an integer multiple of 1 / command_rate.
    command_rate : float, optional
        Command grid [Hz].
    rtol : float, optional
        CVODE's relative tolerance.
    atol : dict, optional
        Absolute tolerances by state: any of ``position`` [m] (default 1e-8), ``velocity`` [m/s]
        (1e-8), ``pressure`` [Pa] (1.0), ``spool`` [-] (1e-8).
    max_steps_per_interval : int, optional
        CVODE's step limit per command interval.
    sensor_noise : bool, optional
        Add the inclinometer noise to ``measured_angle``.
    noise_seed : int, optional
        Its seed.
    initial_position : float, optional
        h0 [m]; None: mid-stroke.
    load : Command or callable, optional
        External load F_L(t) [N] opposing extension; None: none.
    
    Returns
    -------
    Trajectory
        float64 arrays on the output grid, sample k at ``time[k] = k * sample_time``: ``time`` [s],
        ``command`` [V], ``input`` u = V - V0 [V], ``position`` h [m], ``velocity`` v [m/s],
        ``head_pressure`` p1 [Pa], ``rod_pressure`` p2 [Pa], ``spool`` xv [-], ``pilot`` xc [-],
        ``head_flow`` Q1 [m^3/s], ``rod_flow`` Q2 [m^3/s], ``joint_angle`` theta [rad],
        ``joint_rate`` [rad/s], ``pin_angle`` theta_m [rad], ``measured_angle`` [rad]; and the scalars
        ``min_position``, ``max_position`` [m], ``reached_end_stop`` (bool), ``steps`` (CVODE's).
    
    Raises
    ------
    ValueError
        For non-physical parameters or bad options, naming them.
    bonl.NumericalError
        When CVODE fails (its flag and the time reached are in the message).
    """

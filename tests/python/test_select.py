"""bonl.select and bonl.grid: order and structure selection, ranked by criteria recomputed here from
bonl.identify and free-run simulation, on the local cores, on a given executor and on a Dask cluster;
and the same table as C++'s bonl::select gives."""

import concurrent.futures
import math

import numpy as np
import pytest

import bonl


def _system():
    truth = bonl.Hammerstein(2, 1, 2, 2, b=[1, 0.5], a=[-0.6, 0.1], f=[0, 1, 0.3], p=[0, 0, -0.2])
    u = np.repeat(np.random.default_rng(1).uniform(-1, 1, 400), 5)
    y = truth.simulate(u) + np.random.default_rng(2).normal(0, 0.01, u.size)
    return truth, u, y


def _candidates():
    return (bonl.grid(bonl.Hammerstein, na=[1, 2], nb=[1], nk=[1, 2, 3], r=[2])
            + bonl.grid(bonl.ARX, na=[2], nb=[1], nk=[2]))


def test_grid_is_every_combination_of_the_orders():
    structures = bonl.grid(bonl.HammersteinWiener, na=[1, 2], nb=1, nk=[0, 3], r=[2], r1=[2, 3])
    assert len(structures) == 8
    assert {s.orders for s in structures} == {(na, 1, nk, 2, r1, 0) for na in (1, 2) for nk in (0, 3) for r1 in (2, 3)}
    assert bonl.HammersteinWiener.ORDERS == ("na", "nb", "nk", "r", "r1", "ni")
    assert {s.ni for s in bonl.grid(bonl.ARX, na=1, nb=0, nk=0, ni=[0, 1])} == {0, 1}


@pytest.mark.parametrize("criterion", ["validation", "aic", "bic"])
def test_the_true_structure_ranks_first_and_is_refitted_on_all_the_data(criterion):
    truth, u, y = _system()
    result = bonl.select(_candidates(), u, y, criterion=criterion)
    scores = [row.score for row in result.table]
    assert scores == sorted(scores)
    assert (result.table[0].name, result.table[0].orders) == ("Hammerstein", {"na": 2, "nb": 1, "nk": 2, "r": 2})
    np.testing.assert_array_equal(result.best.theta, bonl.identify(bonl.Hammerstein(2, 1, 2, 2), u, y).theta)


def test_scores_are_the_criteria_recomputed_from_identify_and_free_run_simulation():
    _, u, y = _system()
    structure = bonl.Hammerstein(1, 1, 2, 2)
    split = u.size - round(0.25 * u.size)
    (row,) = bonl.select([structure], u, y).table
    fitted = bonl.identify(structure, records=[(u[:split], y[:split])])
    tail = y[split:] - fitted.simulate(u)[split:]
    assert row.validation_mse == row.score == pytest.approx(float(tail @ tail) / tail.size, rel=1e-12)
    (row,) = bonl.select([structure], u, y, criterion="bic").table
    fitted = bonl.identify(structure, records=[(u, y)])
    mse = float(np.mean((y - fitted.simulate(u)) ** 2))
    assert row.fit_mse == pytest.approx(mse, rel=1e-12)
    assert row.score == pytest.approx(u.size * math.log(mse) + structure.num_params * math.log(u.size), rel=1e-12)


def _same_table(python, cpp):
    """The ranked tables of bonl.select and of C++'s bonl::select (bonl._bonl._select): the same
    candidates in the same order, the same failures, the same figures to 1e-12 relative."""
    cpp_table, cpp_best = cpp
    assert [(r.name, r.orders) for r in python.table] == [(type(s).__name__, bonl.named_orders(s)) for s, _ in cpp_table]
    for row, (_, (score, fit_mse, validation_mse, error, model, fold_mse)) in zip(python.table, cpp_table):
        assert row.error == error
        assert (row.model is None) == (model is None)
        assert row.score == pytest.approx(score, rel=1e-12)
        assert row.fit_mse == pytest.approx(fit_mse, rel=1e-12)
        assert row.validation_mse == (None if validation_mse is None else pytest.approx(validation_mse, rel=1e-12))
        assert row.fold_mse == (None if fold_mse is None else pytest.approx(fold_mse, rel=1e-12))
    np.testing.assert_allclose(python.best.theta, cpp_best.theta, rtol=1e-12)


def _ten_samples():
    """A record of 10 samples: at validation_fraction 0.25 the held-out part is 2.5 rounded half away
    from zero, 3 samples (Python's round() gave 2), so 7 parameters cannot be fitted on its fit part."""
    truth = bonl.ARX(1, 1, 0, b=[0.5, 0.3], a=[-0.4])
    u = np.random.default_rng(4).uniform(-1, 1, 10)
    return u, truth.simulate(u) + np.random.default_rng(5).normal(0, 0.01, u.size)


@pytest.mark.parametrize("case", ["ten samples", "window", "several records, aic", "bic", "cross-validation"])
def test_python_and_cpp_select_give_the_same_table(case):
    truth, u, y = _system()
    records, options = [(u, y)], {}
    candidates = bonl.grid(bonl.Hammerstein, na=[1, 2], nb=[1], nk=[1, 2, 3], r=[2]) + [bonl.Hammerstein(1, 2500, 0, 2)]
    if case == "ten samples":
        records = [_ten_samples()]
        candidates = bonl.grid(bonl.ARX, na=[1, 2, 3], nb=[1, 3], nk=[0])  # ARX(3, 3, 0): 7 parameters
    elif case == "window":
        options = dict(window=7)
    elif case == "several records, aic":
        records = [(u[:1001], y[:1001]), (u[1001:], truth.simulate(u[1001:]))]
        options = dict(criterion="aic", passes=2)
    elif case == "cross-validation":
        records = [(u[:1001], y[:1001]), (u[1001:], y[1001:])]
        options = dict(criterion="cross_validation", folds=3, window=4)
    else:
        options = dict(criterion="bic", validation_fraction=0.3)
    python = bonl.select(candidates, records=records, **options)
    cpp = bonl._bonl._select(candidates, bonl._bonl._selection_data(records=records, **options))
    _same_table(python, cpp)
    failed = [row for row in python.table if row.error is not None]
    assert len(failed) == 1 and python.table[-1] is failed[0] and failed[0].score == math.inf
    if case == "ten samples":
        assert failed[0].orders == {"na": 3, "nb": 3, "nk": 0}
        assert failed[0].error == "bonl: select: 7 parameters cannot be fitted on the 7 samples of the fit part"
        (fit_u, fit_y), = records
        row = next(r for r in python.table if r.orders == {"na": 1, "nb": 1, "nk": 0})
        fitted = bonl.identify(bonl.ARX(1, 1, 0), fit_u[:7], fit_y[:7])
        assert row.validation_mse == pytest.approx(float(np.mean((fit_y - fitted.simulate(fit_u))[7:] ** 2)), rel=1e-12)


def test_with_a_window_the_held_out_part_is_scored_after_its_first_samples():
    _, u, y = _system()
    structure = bonl.Hammerstein(1, 1, 2, 2)
    split = u.size - round(0.25 * u.size)
    (row,) = bonl.select([structure], u, y, window=7).table
    fitted = bonl.identify(structure, records=[(u[:split], y[:split])])
    after = y[split + 7:] - fitted.simulate(u[split + 7:], initial=(u[split:split + 7], y[split:split + 7]))
    assert row.validation_mse == row.score == pytest.approx(float(after @ after) / after.size, rel=1e-12)


def test_several_records_hold_out_the_end_of_each():
    truth, u, y = _system()
    records = [(u[:1000], y[:1000]), (u[1000:], truth.simulate(u[1000:]))]
    result = bonl.select(_candidates(), records=records)
    assert result.table[0].orders == {"na": 2, "nb": 1, "nk": 2, "r": 2}


def test_an_executor_of_ones_own_gives_the_same_table():
    _, u, y = _system()
    local = bonl.select(_candidates(), u, y)
    with concurrent.futures.ThreadPoolExecutor(max_workers=1) as executor:
        given = bonl.select(_candidates(), u, y, executor=executor)
    assert [(r.name, r.orders, r.score) for r in given.table] == [(r.name, r.orders, r.score) for r in local.table]


def test_a_dask_cluster_runs_the_grid_and_gives_the_same_table():
    import distributed
    _, u, y = _system()
    local = bonl.select(_candidates(), u, y)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            remote = bonl.select(_candidates(), u, y, executor=client.get_executor())
    assert [(r.name, r.orders, r.score) for r in remote.table] == [(r.name, r.orders, r.score) for r in local.table]
    np.testing.assert_array_equal(remote.best.theta, local.best.theta)


class _LosesTheSecondCandidate(concurrent.futures.ThreadPoolExecutor):
    """An executor that fails one submission, as a cluster does when a worker dies under it."""

    def __init__(self):
        super().__init__(max_workers=1)
        self.submitted = 0

    def submit(self, fn, *args, **kwargs):
        self.submitted += 1
        if self.submitted == 2:
            future = concurrent.futures.Future()
            future.set_exception(RuntimeError("worker lost"))
            return future
        return super().submit(fn, *args, **kwargs)


def test_a_candidate_the_executor_fails_is_reported_and_the_rest_are_kept():
    _, u, y = _system()
    local = bonl.select(_candidates(), u, y)
    with _LosesTheSecondCandidate() as executor:
        given = bonl.select(_candidates(), u, y, executor=executor)
    lost = _candidates()[1]
    assert given.table[-1].orders == bonl.named_orders(lost)
    assert given.table[-1].error == "executor: RuntimeError: worker lost"
    assert given.table[-1].score == math.inf and given.table[-1].model is None
    kept = [(r.name, r.orders, r.score) for r in local.table if r.orders != given.table[-1].orders]
    assert [(r.name, r.orders, r.score) for r in given.table[:-1]] == kept
    np.testing.assert_array_equal(given.best.theta, local.best.theta)


def test_a_candidate_with_more_parameters_than_the_fit_part_has_samples_is_ranked_as_failed():
    """Ranked last with why, the others kept, as C++'s bonl::select does; only when every candidate is
    too large does the selection fail."""
    truth = bonl.ARX(1, 1, 0, b=[0.5, 0.3], a=[-0.4])
    u = np.random.default_rng(3).uniform(-1, 1, 40)
    y = truth.simulate(u)
    large = bonl.ARX(20, 20, 0)  # 41 parameters, 30 samples in the fit part
    selection = bonl.select([bonl.ARX(1, 1, 0), large], u, y)
    assert selection.table[0].orders == {"na": 1, "nb": 1, "nk": 0}
    assert selection.table[-1].orders == bonl.named_orders(large) and selection.table[-1].model is None
    assert selection.table[-1].score == math.inf
    assert "41 parameters cannot be fitted on the 30 samples" in selection.table[-1].error
    np.testing.assert_allclose(selection.best.theta, truth.theta, atol=1e-9)
    with pytest.raises(bonl.NumericalError, match="every candidate failed"):
        bonl.select([large], u, y)


def test_progress_bar_on_request(capsys):
    _, u, y = _system()
    bonl.select(_candidates()[:2], u, y, progress=True)
    assert "bonl.select" in capsys.readouterr().err
    bonl.select(_candidates()[:2], u, y, progress=False)
    assert "bonl.select" not in capsys.readouterr().err


@pytest.mark.parametrize("call, message", [
    (lambda u, y: bonl.select([], u, y), "candidates is empty"),
    (lambda u, y: bonl.select([bonl.ARX(2, 1, 0), "ARX"], u, y), r"candidates\[1\] must be a bonl model, got str"),
    (lambda u, y: bonl.select([bonl.ARX(2, 1, 0)], u, y, criterion="mdl"),
     "criterion must be one of validation, aic, bic, cross_validation"),
    (lambda u, y: bonl.select([bonl.ARX(2, 1, 0)], u, y, criterion="cross_validation", folds=1),
     "folds must be >= 2, got 1"),
    (lambda u, y: bonl.select([bonl.ARX(2, 1, 0)], u, y, criterion="cross_validation", folds=True),
     "folds must be an integer >= 2, got True"),
    (lambda u, y: bonl.select([bonl.ARX(2, 1, 0)], u, y, criterion="cross_validation", fold_initial_state="zero"),
     "fold_initial_state must be 'measured' or 'estimated', got 'zero'"),
    (lambda u, y: bonl.select([bonl.ARX(2, 1, 0)], u, y, fold_initial_state="estimated"),
     "fold_initial_state 'estimated' applies to criterion 'cross_validation' only, got criterion 'validation'"),
    (lambda u, y: bonl.select([bonl.ARX(2, 1, 0)], u, y, validation_fraction=1.0), r"validation_fraction must be in \(0, 1\)"),
    (lambda u, y: bonl.select([bonl.ARX(2, 1, 0)], u, y, window=-1), "window must be an integer >= 0, got -1"),
    (lambda u, y: bonl.select([bonl.ARX(2, 1, 0)], u, y, window=2.5), "window must be an integer >= 0, got 2.5"),
    (lambda u, y: bonl.select([bonl.ARX(2, 1, 0)], u, y, window=5, criterion="aic"),
     "window applies to criteria 'validation' and 'cross_validation' only"),
    (lambda u, y: bonl.select([bonl.ARX(2, 1, 0)], u, y, window=500),
     r"records\[0\]'s held-out part \(500 samples\) must be longer than the window \(500\)"),
    (lambda u, y: bonl.select([bonl.ARX(2, 1, 0)], u), "y must be a 1-D array of real numbers, got None"),
    (lambda u, y: bonl.select([bonl.ARX(2, 1, 0)], records=[(u, y), u]), r"records\[1\] must be a pair \(u, y\)"),
    (lambda u, y: bonl.select([bonl.ARX(2, 1, 0)], u, y, method="best"), "method must be"),
    (lambda u, y: bonl.grid(bonl.ARX, na=[1], nb=[1]), "ARX takes the orders na, nb, nk, ni; missing: nk"),
    (lambda u, y: bonl.grid(bonl.ARX, na=[1], nb=[1], nk=[0], r=[2]), "unknown: r"),
    (lambda u, y: bonl.grid(int, na=[1]), "model_class must be one of bonl.MODELS"),
], ids=["empty", "not a model", "criterion", "one fold", "boolean folds", "fold state",
        "fold state without folds", "fraction", "negative window", "fractional window", "window with aic",
        "window too long", "no y", "not a pair", "identify option", "grid missing",
        "grid unknown", "grid class"])
def test_bad_input_is_a_value_error(call, message):
    _, u, y = _system()
    with pytest.raises(ValueError, match=message):
        call(u, y)


def test_a_model_whose_free_run_diverges_beyond_the_measured_inputs_is_not_chosen():
    """y(k) = 0.5 y(k-1) + 0.17 u(k-1) + 0.5 y(k-1)^3 is stable for |u| <= 1 and diverges for inputs 1.25
    times larger (the oracle: its own free run, here). Its structure fits the held-out data exactly and is
    refused with the reason; the linear structure (r = 1) is chosen, as C++'s bonl::select chooses."""
    truth = bonl.NonlinearFeedback(1, 0, 1, 3, 0, 1, 0, b=[0.17], a=[-0.5], f=[0.0, 0.5])
    u = np.repeat(np.random.default_rng(4).uniform(-1, 1, 30), 40)  # long holds: time to diverge
    y = truth.simulate(u)
    assert np.all(np.isfinite(y))
    with pytest.raises(bonl.NumericalError):
        truth.simulate(1.25 * u)
    candidates = [bonl.NonlinearFeedback(1, 0, 1, 3, 0, 1, 0), bonl.NonlinearFeedback(1, 0, 1, 1, 0, 1, 0)]
    selection = bonl.select(candidates, u, y)
    assert [row.orders["r"] for row in selection.table] == [1, 3]
    refused = selection.table[1]
    assert refused.score == math.inf and refused.model is not None
    assert "free run diverges on records[0]'s input stretched 1.25 times about u0" in refused.error
    assert selection.best.r == 1 and np.all(np.isfinite(selection.best.simulate(1.25 * u)))
    cpp_table, cpp_best = bonl._bonl._select(candidates, bonl._bonl._selection_data(u, y))
    assert [row[1][0] for row in cpp_table] == [row.score for row in selection.table]
    np.testing.assert_array_equal(cpp_best.theta, selection.best.theta)
    with pytest.raises(bonl.NumericalError, match="none has a finite score and a bounded free run"):
        bonl.select(candidates[:1], u, y)


@pytest.mark.parametrize("fold_initial_state", ["measured", "estimated"])
def test_cross_validation_survives_pickling_as_a_dask_worker_receives_it(fold_initial_state):
    import pickle
    _, u, y = _system()
    data = bonl._bonl._selection_data(u, y, criterion="cross_validation", folds=4, window=3,
                                      fold_initial_state=fold_initial_state)
    copy = pickle.loads(pickle.dumps(data))
    structure = bonl.Hammerstein(2, 1, 2, 2)
    original, received = bonl._bonl._score_candidate(structure, data), bonl._bonl._score_candidate(structure, copy)
    assert len(original[5]) == 4
    assert received[0] == original[0] and received[5] == original[5]
    # The folds' state travels with the data: the other state scores differently.
    other = bonl._bonl._selection_data(u, y, criterion="cross_validation", folds=4, window=3,
                                       fold_initial_state="estimated" if fold_initial_state == "measured"
                                       else "measured")
    assert bonl._bonl._score_candidate(structure, other)[0] != received[0]

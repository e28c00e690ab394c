# Type stubs of the cv_essential extension module (python/src/cv_essential_module.cpp), for editors
# and type checkers. python/tests/test_stubs.py checks that they name exactly the module's API.
from typing import Callable, List, Optional, Sequence, Tuple, overload

import numpy as np

Array = np.ndarray

class EssentialParams:
    solver: str
    method: int
    engine: int
    timeBudgetMs: float
    preemptiveHypotheses: int
    preemptiveBlockSize: int
    confidence: float
    threshold: float
    distance: int
    maxIters: int
    sampleBudget: int
    budgetLocalSamples: bool
    planeParallax: bool
    loIterations: int
    loSampleSize: int
    sampler: int
    sprt: bool
    seed: int
    refine: bool
    recoverPose: bool
    def __init__(self, **fields: object) -> None: ...

class EssentialReport:
    success: bool
    E: Array
    R: Array
    t: Array
    poseRecovered: bool
    pointsInFront: int
    degenerate: bool
    numPoints: int
    inliers: int
    iterations: int
    hypothesesGenerated: int
    planeParallaxKept: bool
    timeTotalMs: float

class EssentialPairResult:
    E: Array
    mask: Array
    report: EssentialReport
    error: str

@overload
def findEssentialMatIter(points1: Array, points2: Array, cameraMatrix: Array, method: int = ...,
                         prob: float = ..., threshold: float = ..., maxIters: int = ...,
                         mask: Optional[Array] = ...) -> Tuple[Array, Optional[Array]]: ...
@overload
def findEssentialMatIter(points1: Array, points2: Array, focal: float = ...,
                         pp: Tuple[float, float] = ..., method: int = ..., prob: float = ...,
                         threshold: float = ..., maxIters: int = ...,
                         mask: Optional[Array] = ...) -> Tuple[Array, Optional[Array]]: ...
@overload
def findEssentialMatIter(points1: Array, points2: Array, cameraMatrix1: Array,
                         distCoeffs1: Optional[Array], cameraMatrix2: Array,
                         distCoeffs2: Optional[Array], method: int = ..., prob: float = ...,
                         threshold: float = ...,
                         mask: Optional[Array] = ...) -> Tuple[Array, Optional[Array]]: ...
@overload
def findEssentialMatIter(points1: Array, points2: Array, cameraMatrix1: Array,
                         cameraMatrix2: Array, dist_coeff1: Optional[Array],
                         dist_coeff2: Optional[Array], params: object,
                         mask: Optional[Array] = ...) -> Tuple[Array, Optional[Array]]: ...
@overload
def findEssentialMatIter(points1: Array, points2: Array, cameraMatrix: Array,
                         params: EssentialParams, mask: Optional[Array] = ...
                         ) -> Tuple[Array, Optional[Array], EssentialReport]: ...

@overload
def recoverPose(points1: Array, points2: Array, cameraMatrix1: Array,
                distCoeffs1: Optional[Array], cameraMatrix2: Array, distCoeffs2: Optional[Array],
                E: object = ..., R: object = ..., t: object = ..., method: int = ...,
                prob: float = ..., threshold: float = ..., mask: Optional[Array] = ...
                ) -> Tuple[int, Array, Array, Array, Optional[Array]]: ...
@overload
def recoverPose(E: Array, points1: Array, points2: Array, cameraMatrix: Array, R: object = ...,
                t: object = ..., mask: Optional[Array] = ...
                ) -> Tuple[int, Array, Array, Optional[Array]]: ...
@overload
def recoverPose(E: Array, points1: Array, points2: Array, cameraMatrix: Array,
                distanceThresh: float, R: object = ..., t: object = ...,
                mask: Optional[Array] = ..., triangulatedPoints: object = ...
                ) -> Tuple[int, Array, Array, Optional[Array], Array]: ...
@overload
def recoverPose(E: Array, points1: Array, points2: Array, R: object = ..., t: object = ...,
                focal: float = ..., pp: Tuple[float, float] = ...,
                mask: Optional[Array] = ...) -> Tuple[int, Array, Array, Optional[Array]]: ...

def listSolvers() -> List[str]: ...
def registerSolver(name: str, solver: Callable[[Array, Array], Sequence[Array]],
                   sampleSize: int = ..., maxSolutions: int = ...,
                   successRate: float = ...) -> None: ...
def findEssentialMatBatch(pairs: Sequence[Tuple[Array, Array, Array]],
                          params: Optional[EssentialParams] = ..., threads: int = ...,
                          progress: object = ...) -> List[EssentialPairResult]: ...
def batchPairSeed(seed: int, index: int) -> int: ...

# Type stubs of the cv_essential extension module (python/src/), for editors and type checkers.
# python/tests/test_stubs.py checks that they name exactly the module's API.
# The EssentialParams and EssentialReport classes are written by scripts/params_table.py from the
# C++ structs in opencv2/essential/params.hpp.
from typing import Callable, List, Optional, Sequence, Tuple, Union, overload

import numpy as np

Array = np.ndarray
# What cv2 4.6 accepts for an array argument (python/README.md, "Point layouts").
ArrayLike = Union[np.ndarray, float, int, Tuple[float, ...], None]

ENGINE_ADAPTIVE: int
ENGINE_OPENCV: int
ENGINE_PREEMPTIVE: int
DISTANCE_SAMPSON: int
DISTANCE_SYMMETRIC_EPIPOLAR: int
BUDGET_CONFIDENCE: int
BUDGET_OPENCV_TIME: int

class EssentialParams:
    confidence: float
    threshold: float
    maxIterations: int
    distance: int
    seed: int
    solver: str
    engine: int
    score: int
    sampler: int
    sprt: bool
    sampleBudget: int
    timeBudgetMs: float
    preemptiveHypotheses: int
    preemptiveBlockSize: int
    loIterations: int
    loSampleSize: int
    budgetLocalSamples: bool
    planeParallax: bool
    inFrontCheck: bool
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
    rotationOnlyFraction: float
    homographyFraction: float
    degenerate: bool
    numPoints: int
    inliers: int
    iterations: int
    hypothesesGenerated: int
    hypothesesConverged: int
    hypothesesScored: int
    refineIterations: int
    pointsScored: int
    localOptimisations: int
    localOptimisationsKept: int
    sprtRejections: int
    planeParallaxKept: bool
    inFrontSearch: bool
    inFrontSearchKept: bool
    timeSetupMs: float
    timeSearchMs: float
    timeRefineMs: float
    timePoseMs: float
    timeTotalMs: float

class EssentialPairResult:
    E: Optional[Array]
    mask: Array
    report: EssentialReport
    error: str

@overload
def findEssentialMatIter(points1: ArrayLike, points2: ArrayLike, cameraMatrix: ArrayLike, method: int = ...,
                         prob: float = ..., threshold: float = ..., maxIters: int = ...,
                         mask: ArrayLike = ...) -> Tuple[Optional[Array], Optional[Array]]: ...
@overload
def findEssentialMatIter(points1: ArrayLike, points2: ArrayLike, focal: float = ...,
                         pp: Tuple[float, float] = ..., method: int = ..., prob: float = ...,
                         threshold: float = ..., maxIters: int = ...,
                         mask: ArrayLike = ...) -> Tuple[Optional[Array], Optional[Array]]: ...
@overload
def findEssentialMatIter(points1: ArrayLike, points2: ArrayLike, cameraMatrix1: ArrayLike,
                         distCoeffs1: Optional[Array], cameraMatrix2: ArrayLike,
                         distCoeffs2: Optional[Array], method: int = ..., prob: float = ...,
                         threshold: float = ...,
                         mask: ArrayLike = ...) -> Tuple[Optional[Array], Optional[Array]]: ...
@overload
def findEssentialMatIter(points1: ArrayLike, points2: ArrayLike, cameraMatrix1: ArrayLike,
                         cameraMatrix2: ArrayLike, dist_coeff1: Optional[Array],
                         dist_coeff2: Optional[Array], params: object,
                         mask: ArrayLike = ...) -> Tuple[Optional[Array], Optional[Array]]: ...
@overload
def findEssentialMatIter(points1: ArrayLike, points2: ArrayLike, cameraMatrix: ArrayLike,
                         params: EssentialParams, mask: ArrayLike = ...
                         ) -> Tuple[Optional[Array], Optional[Array], EssentialReport]: ...

@overload
def recoverPose(points1: ArrayLike, points2: ArrayLike, cameraMatrix1: ArrayLike,
                distCoeffs1: Optional[Array], cameraMatrix2: ArrayLike, distCoeffs2: Optional[Array],
                E: ArrayLike = ..., R: ArrayLike = ..., t: ArrayLike = ..., method: int = ...,
                prob: float = ..., threshold: float = ..., mask: ArrayLike = ...
                ) -> Tuple[int, Array, Array, Array, Optional[Array]]: ...
@overload
def recoverPose(E: ArrayLike, points1: ArrayLike, points2: ArrayLike, cameraMatrix: ArrayLike, R: ArrayLike = ...,
                t: ArrayLike = ..., mask: ArrayLike = ...
                ) -> Tuple[int, Array, Array, Optional[Array]]: ...
@overload
def recoverPose(E: ArrayLike, points1: ArrayLike, points2: ArrayLike, cameraMatrix: ArrayLike,
                distanceThresh: float, R: ArrayLike = ..., t: ArrayLike = ...,
                mask: ArrayLike = ..., triangulatedPoints: ArrayLike = ...
                ) -> Tuple[int, Array, Array, Optional[Array], Array]: ...
@overload
def recoverPose(E: ArrayLike, points1: ArrayLike, points2: ArrayLike, R: ArrayLike = ..., t: ArrayLike = ...,
                focal: float = ..., pp: Tuple[float, float] = ...,
                mask: ArrayLike = ...) -> Tuple[int, Array, Array, Optional[Array]]: ...

# The C++ API's name (cv::essential::recoverPoseIter); the same function.
recoverPoseIter = recoverPose

def listSolvers() -> List[str]: ...
def isOpenCvLoopAvailable() -> bool: ...
def registerSolver(name: str, solver: Callable[[Array, Array], Sequence[Array]],
                   sampleSize: int = ..., maxSolutions: int = ...,
                   successRate: float = ...) -> None: ...
def findEssentialMatBatch(pairs: Sequence[Tuple[ArrayLike, ArrayLike, ArrayLike]],
                          params: Optional[EssentialParams] = ..., threads: int = ...,
                          progress: object = ..., firstIndex: int = ...
                          ) -> List[EssentialPairResult]: ...
def batchPairSeed(seed: int, index: int) -> int: ...

# File > Open, Save and Save As of a parameter file shown instead of a drive.
target_sources(drivedesk_ui PRIVATE
    files/ParameterFileFeature.cpp files/ParameterFileFeature.h
)

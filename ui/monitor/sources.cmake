# The telegram monitor dock and its window feature: the traffic model and its filter, formatting and saving.
target_sources(drivedesk_ui PRIVATE
    monitor/MonitorFeature.cpp monitor/MonitorFeature.h
    monitor/TelegramMonitor.cpp monitor/TelegramMonitorFiles.cpp monitor/TelegramMonitor.h
    monitor/TrafficFile.cpp monitor/TrafficFile.h
    monitor/TrafficFilterModel.cpp monitor/TrafficFilterModel.h
    monitor/TrafficFormat.cpp monitor/TrafficFormat.h
    monitor/TrafficModel.cpp monitor/TrafficModel.h
)
